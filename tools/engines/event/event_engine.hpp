#pragma once
// The event-driven integrator as an engine of `impactbench run/compare/suite`: builds our model
// of a scenario (engines::build_system), reads EventDrivenOptions from the resolved settings
// (keys: event_settings.hpp) and maps the result onto engines::RunResult (trajectory samples,
// events, run summary).
#include "lib/engines/event_driven/event_driven_options.hpp"
#include "lib/engines/run_result.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::engines::event_driven {

/// Throws SettingError naming an unknown setting key or a refused value.
EventDrivenOptions options_from(const RunOptions& options);

/// Runs with `options` (parsed once by the registry) for run.duration, recording as
/// run.recording asks; RunResult::settings is left to the registry. Throws std::runtime_error
/// with the run's status message when the run fails.
RunResult run_event_driven(const scenario::Scenario& scenario, const EventDrivenOptions& options,
                           const RunOptions& run);

}  // namespace impactbench::engines::event_driven
