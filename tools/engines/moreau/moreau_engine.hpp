#pragma once
// The Moreau–Jean stepper as an engine of `impactbench run/compare/suite`: builds our model of a
// scenario, reads MoreauJeanOptions from the resolved settings (keys: moreau_settings.hpp) and
// maps the simulation onto engines::RunResult. Impacts and lift-offs in the events CSV are the
// steps where a contact enters or leaves the one-step problem.
#include "lib/engines/moreau_jean/moreau_jean_options.hpp"
#include "lib/engines/run_result.hpp"

namespace impactbench::engines::moreau_jean {

/// Throws SettingError naming an unknown setting key or a refused value.
MoreauJeanOptions options_from(const RunOptions& options);

/// Runs with `settings` (parsed once by the registry) for run.duration, recording as
/// run.recording asks; RunResult::settings is left to the registry. Throws std::runtime_error
/// with the run's status message when the run stops early.
RunResult run_moreau_jean(const scenario::Scenario& scenario, const MoreauJeanOptions& settings,
                          const RunOptions& run);

}  // namespace impactbench::engines::moreau_jean
