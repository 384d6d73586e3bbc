#pragma once
// The event-driven integrator as an engine of `impactbench run/compare/suite`: builds our model
// of a scenario (engines::build_system), maps RunOptions onto EventDrivenOptions and the result
// onto engines::RunResult (trajectory samples, events, run summary).
//
// RunOptions: `tolerance` sets both CVODE tolerances; `solver` names the contact solver (an
// LCP solver name goes to the planar/normal problems, any other to the spatial friction
// problems). `settings` keys (numbers unless noted): rtol, atol, method (bdf|adams),
// max_events, output_interval, max_step, zeno_impact_count, zeno_velocity, zeno_min_interval,
// gap_tolerance, velocity_tolerance, lcp_solver (name), friction_solver (name).
#include "lib/engines/event_driven/event_driven_options.hpp"
#include "lib/engines/run_result.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::engines::event_driven {

/// Throws std::invalid_argument naming an unknown setting key or a malformed value.
EventDrivenOptions options_from(const RunOptions& options);

/// Throws std::runtime_error with the run's status message when the run fails.
RunResult run_event_driven(const scenario::Scenario& scenario, const RunOptions& options);

}  // namespace impactbench::engines::event_driven
