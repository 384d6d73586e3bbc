#include "tests/test_utilities/scenario_runs.hpp"

#include "tools/adapters/engine_registry.hpp"

namespace impactbench::test_support {

engines::RunResult run_with_scenario_defaults(const std::string& engine,
                                              const scenario::Scenario& scenario) {
  engines::RunOptions options;
  options.engine = engine;
  options.dt = scenario.dt;
  options.tolerance = scenario.tolerance;
  options.duration = scenario.duration;
  return adapters::run_engine(engine, scenario, options);
}

}  // namespace impactbench::test_support
