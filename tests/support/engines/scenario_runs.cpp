#include "tests/support/engines/scenario_runs.hpp"

#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"

namespace impactbench::test_support {

engines::RunResult run_with_scenario_defaults(const std::string& engine,
                                              const scenario::Scenario& scenario) {
  return adapters::run_engine(engine, scenario, engines::resolve_run_options(engine, scenario));
}

}  // namespace impactbench::test_support
