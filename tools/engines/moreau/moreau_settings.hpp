#pragma once
// The Moreau–Jean engine's settings: every key `--option` and a scenario's [settings.moreau]
// accept, with its range, over MoreauJeanOptions. --dt sets dt, --tol sets tolerance and
// --solver sets solver; the scenario's dt and tolerance do the same at lower precedence.
#include "lib/engines/moreau_jean/moreau_jean_options.hpp"
#include "lib/engines/settings/engine_settings.hpp"

namespace impactbench::engines::moreau_jean {

const SettingsSchema<MoreauJeanOptions>& moreau_settings_schema();
const EngineSettings& moreau_settings();

}  // namespace impactbench::engines::moreau_jean
