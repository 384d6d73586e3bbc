#pragma once
// A scenario run as `impactbench run SCENARIO --engine ENGINE` does it with no options: through
// the engine registry (adapters::run_engine) with the scenario's own step, tolerance and
// duration and the engine's default settings. The tests' one way to run a scenario file.
#include <string>

#include "lib/engines/run_result.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::test_support {

engines::RunResult run_with_scenario_defaults(const std::string& engine,
                                              const scenario::Scenario& scenario);

}  // namespace impactbench::test_support
