#pragma once
// Every engine by name, behind one call: the only list of the engines. `impactbench
// run/compare/suite`, the settings catalog (run_settings.hpp), the scenario loader (through
// engine_catalog()), the tests and the benchmarks all enumerate it. Adding an engine is one
// entry here (docs/development.md).
#include <string>
#include <utility>
#include <vector>

#include "lib/engines/run_result.hpp"
#include "lib/engines/settings/engine_settings.hpp"
#include "lib/scenario/engine_catalog.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::adapters {

using engines::EngineFunction;
using engines::RunOptions;

struct EngineInfo {
  std::string name;  ///< as on the command line and in a scenario's `engines`
  std::string description;
  const engines::EngineSettings* settings = nullptr;  ///< its keys and flags (never null)
  EngineFunction run;  ///< empty: the engine is not built (an optional library was missing)
  /// `--option` pairs under which it is compared at equal work (issue #13's table); empty:
  /// not in that table.
  std::vector<std::pair<std::string, std::string>> equal_work;
  /// Whether it runs RecordingOptions::timing_only (bare loops for the equal-work timing).
  bool timing_only_runs = false;
  /// Where its contacts hold energy that the bodies' kinetic + potential energy leaves out
  /// (a soft or position-corrected contact); empty for hard contacts.
  std::string contact_energy = {};
};

/// All engines, in the order compare tables list them.
const std::vector<EngineInfo>& engine_registry();

/// nullptr for an unknown name.
const EngineInfo* find_engine(const std::string& name);

/// The engines' names, in registry order.
const std::vector<std::string>& engine_names();

/// The registry as the scenario loader sees it: names and each engine's settings check.
const scenario::EngineCatalog& engine_catalog();

/// The one line that refuses an engine whose `run` is empty.
std::string not_built_message(const std::string& engine);

/// Runs `engine` on `scenario`. Throws std::invalid_argument for an unknown or unavailable
/// engine or one the scenario does not list, and whatever the engine throws for settings it
/// rejects.
engines::RunResult run_engine(const std::string& engine, const scenario::Scenario& scenario,
                              const RunOptions& options);

}  // namespace impactbench::adapters
