#include "tests/support/engines/reference_engine_runs.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::test_support {

double named(const compare::NamedValues& values, const std::string& name) {
  for (const auto& [n, v] : values)
    if (n == name) return v;
  ADD_FAILURE() << "no metric " << name;
  return std::nan("");
}

Eigen::Index column_index(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) {
    ADD_FAILURE() << "no trajectory column " << name;
    return -1;
  }
  return static_cast<Eigen::Index>(it - names.begin());
}

compare::NamedValues run_and_measure(
    const std::string& engine, const std::string& scenario_name,
    const scenario::ParameterOverrides& overrides, double duration,
    const std::vector<std::pair<std::string, std::string>>& options) {
  const auto s = scenario::load_scenario_by_name(scenario_name, overrides);
  engines::SettingsRequest request;
  if (duration > 0.0) request.duration = duration;
  request.options = options;
  return compare::analytic_errors(
      s, adapters::run_engine(engine, s, engines::resolve_run_options(engine, s, request)));
}

void expect_refused_settings(const std::string& engine, const std::string& scenario_name,
                             const std::vector<std::pair<std::string, std::string>>& refused) {
  const auto s = scenario::load_scenario_by_name(scenario_name);
  engines::SettingsRequest request;
  for (const auto& [key, value] : refused) {
    request.options = {{key, value}};
    try {
      engines::resolve_run_options(engine, s, request);
      ADD_FAILURE() << engine << ": " << key << "=" << value << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

}  // namespace impactbench::test_support
