#pragma once
// How an engine is asked to run a scenario and what it gives back; the `impactbench run`
// command (tools/cli/engine_registry.cpp) maps engine names to functions of this shape.
#include <functional>
#include <string>
#include <vector>

#include "lib/output/trajectory.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::scenario {

/// Settings of one run, defaults already resolved from the scenario.
struct RunOptions {
  std::string engine;
  double dt = 0.0;         ///< step [s] (time-stepping engines)
  double tolerance = 0.0;  ///< event location / integration tolerance (event-driven)
  std::string solver;      ///< one-step solver name; empty = the engine's default
  double duration = 0.0;   ///< simulated time [s]
};

struct RunResult {
  output::Trajectory trajectory;
  std::vector<output::EventRecord> events;
};

/// An engine: runs `scenario` with `options`; throws (std::exception) on failure.
using EngineFunction = std::function<RunResult(const Scenario&, const RunOptions&)>;

}  // namespace impactbench::scenario
