#pragma once
// The one place where an engine's settings for a run are assembled, in order of precedence:
// the engine's defaults, its expert set when asked (`--settings expert`), the scenario file (its dt
// and tolerance for the engines that use them, then its [settings.ENGINE] table), the command
// line's flags (--dt, --tol, --solver) and its --option KEY=VALUE entries. A flag or key the engine
// cannot use is refused, never ignored. `run`, `compare`, `describe`, the suite and the tests all
// resolve through here.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lib/engines/run_result.hpp"
#include "lib/engines/settings/engine_settings.hpp"
#include "lib/engines/settings/settings_set.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::engines {

/// Every engine's settings, in the engine registry's order.
const std::vector<const EngineSettings*>& engine_settings_catalog();
/// nullptr for an unknown engine name.
const EngineSettings* find_engine_settings(const std::string& engine);

/// Whether `set` changes anything for `engine`: kExpert for an engine with an expert set.
bool applies_settings_set(const std::string& engine, SettingsSet set);

/// What the command line asks of one engine's run, beyond the scenario.
struct SettingsRequest {
  /// kExpert: the engine's expert set over its defaults (none for an engine without one).
  SettingsSet set = SettingsSet::kDefault;
  std::optional<double> dt;
  std::optional<double> tolerance;
  std::optional<std::string> solver;
  std::optional<double> duration;
  std::vector<std::pair<std::string, std::string>> options;  ///< --option key=value, in order
  /// Set by compare for the run that serves as the reference trajectory (source "reference
  /// sampling"): over the scenario file, under the command line.
  std::vector<std::pair<std::string, std::string>> reference_sampling;
};

/// Throws std::invalid_argument (SettingError for a refused key or value) naming the engine
/// and what it accepts; every such error is the user's (a usage error), since the scenario's
/// own values were checked when it was loaded.
RunOptions resolve_run_options(const std::string& engine, const scenario::Scenario& scenario,
                               const SettingsRequest& request = {});

/// The value in force of `key` (throws std::out_of_range when the list has no such key).
const std::string& setting_value(const SettingList& settings, const std::string& key);

/// The value in force of a numeric key, a number the schema has checked; subnormal values
/// (1e-310) are read as they are, not refused as std::stod refuses them.
double setting_number(const SettingList& settings, const std::string& key);

/// Empty when `step` [s] can step a run of `duration` [s] (at most the duration, and at most
/// kMaxSteps steps); else why not, e.g. "duration 0.05 s at step 1e-310 s needs 5e308 steps;
/// at most 1e12 are allowed (...)".
std::string step_problem(const std::string& engine, double step, double duration);

}  // namespace impactbench::engines
