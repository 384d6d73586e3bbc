#include "tools/engines/registry/scenario_loading.hpp"

#include "tools/engines/registry/engine_registry.hpp"

namespace impactbench::scenario {

Scenario load_scenario(const std::filesystem::path& path, const ParameterOverrides& overrides,
                       std::optional<double> duration) {
  return load_scenario(adapters::engine_catalog(), path, overrides, duration);
}

Scenario load_scenario_by_name(const std::string& name, const ParameterOverrides& overrides,
                               std::optional<double> duration) {
  return load_scenario_by_name(adapters::engine_catalog(), name, overrides, duration);
}

}  // namespace impactbench::scenario
