#pragma once
// The event-driven engine's settings: every key `--option` and a scenario's [settings.event]
// accept, with its range, over EventDrivenOptions. --tol (and the scenario's tolerance) sets
// rtol and atol; --solver NAME sets lcp_solver when NAME is an LCP solver, else
// friction_solver; the engine has no time step and refuses --dt.
#include "lib/engines/event_driven/event_driven_options.hpp"
#include "lib/engines/settings/engine_settings.hpp"

namespace impactbench::engines::event_driven {

const SettingsSchema<EventDrivenOptions>& event_settings_schema();
const EngineSettings& event_settings();

}  // namespace impactbench::engines::event_driven
