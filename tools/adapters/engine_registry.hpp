#pragma once
// Every engine by name, behind one call: `impactbench run/compare/suite`, the tests and the
// benchmarks all enumerate this list.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lib/engines/run_result.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::adapters {

/// What a run may override; unset fields fall back to the scenario's defaults.
struct RunOptions {
  std::optional<double> dt;         ///< [s] time-stepping engines
  std::optional<double> tolerance;  ///< event-driven integration tolerance
  std::optional<double> duration;   ///< [s]
  std::string solver;               ///< Moreau–Jean one-step solver ("" = default)
  /// Engine-specific settings as key=value (e.g. velocity_iterations=50 for box2d); unknown
  /// keys are an error naming the valid ones.
  std::map<std::string, std::string> settings;
};

using EngineFunction =
    std::function<engines::RunResult(const scenario::Scenario&, const RunOptions&)>;

struct EngineInfo {
  std::string name;
  std::string description;
  EngineFunction run;
};

/// All engines, in the order compare tables list them.
const std::vector<EngineInfo>& engine_registry();

/// Runs `engine` on `scenario`. Throws std::invalid_argument for an unknown engine or one the
/// scenario does not list, and whatever the engine throws for settings it rejects.
engines::RunResult run_engine(const std::string& engine, const scenario::Scenario& scenario,
                              const RunOptions& options);

/// Parses a numeric setting, with an error naming the engine and key.
double setting_number(const std::string& engine, const std::string& key, const std::string& value);

}  // namespace impactbench::adapters
