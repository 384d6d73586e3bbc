#pragma once
// A named set of engine settings chosen as a whole (`--settings default|expert`): `default` is
// every engine's defaults; `expert` applies, for each engine that has one, the values its own
// documentation gives for accurate rigid contact (EngineSettings::expert), between the defaults
// and the scenario file. An engine without an expert set runs its defaults.
#include <string>
#include <vector>

namespace impactbench::engines {

enum class SettingsSet { kDefault, kExpert };

std::string to_string(SettingsSet set);  ///< "default" | "expert"
/// The names of every set, in order: "default", "expert".
const std::vector<std::string>& settings_set_names();
/// The set named `name`; throws std::invalid_argument "unknown settings set 'x' (sets: default
/// or expert)".
SettingsSet parse_settings_set(const std::string& name);

}  // namespace impactbench::engines
