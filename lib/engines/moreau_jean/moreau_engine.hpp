#pragma once
// The Moreau–Jean stepper as an engine of `impactbench run/compare/suite`: builds our model of a
// scenario, maps RunOptions onto MoreauJeanOptions (dt, solver, tolerance) and the simulation
// onto engines::RunResult. Impacts and lift-offs in the events CSV are the steps where a contact
// enters or leaves the one-step problem.
//
// `settings` keys: theta, on_failure (stop|warn), forces (explicit|linearly-implicit),
// max_iterations, contact_margin, cone_facets.
#include "lib/engines/moreau_jean/moreau_jean_options.hpp"
#include "lib/engines/run_result.hpp"

namespace impactbench::engines::moreau_jean {

/// Throws std::invalid_argument naming an unknown setting key or a malformed value.
MoreauJeanOptions options_from(const RunOptions& options);

/// Throws std::runtime_error with the run's status message when the run stops early.
RunResult run_moreau_jean(const scenario::Scenario& scenario, const RunOptions& options);

}  // namespace impactbench::engines::moreau_jean
