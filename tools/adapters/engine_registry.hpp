#pragma once
// Every engine by name, behind one call: `impactbench run/compare/suite`, the tests and the
// benchmarks all enumerate this list. Every name of scenario::known_engines() has an entry.
#include <string>
#include <vector>

#include "lib/engines/run_result.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::adapters {

using engines::EngineFunction;
using engines::RunOptions;

struct EngineInfo {
  std::string name;
  std::string description;
  EngineFunction run;  ///< empty: the engine is not built (an optional library was missing)
};

/// All engines, in the order compare tables list them.
const std::vector<EngineInfo>& engine_registry();

/// nullptr for an unknown name.
const EngineInfo* find_engine(const std::string& name);

/// The one line that refuses an engine whose `run` is empty.
std::string not_built_message(const std::string& engine);

/// Runs `engine` on `scenario`. Throws std::invalid_argument for an unknown or unavailable
/// engine or one the scenario does not list, and whatever the engine throws for settings it
/// rejects.
engines::RunResult run_engine(const std::string& engine, const scenario::Scenario& scenario,
                              const RunOptions& options);

}  // namespace impactbench::adapters
