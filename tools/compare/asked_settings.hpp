#pragma once
// What an engine was asked to do in a run, in one short cell for the suite's per-scenario tables:
// its step, its tolerance, its solver and its iteration limits, as in force. The full list of
// settings with their sources stays in metrics.csv's `settings` column.
#include <string>

#include "lib/engines/run_result.hpp"

namespace impactbench::compare {

/// "dt=0.001 tolerance=1e-10 solver=nsgs max_iterations=1000": the keys of `options.settings`
/// that --dt and --tol set, the solver choices (solver, stepper, method, scheme, cone and the
/// *_solver keys) and every *iterations key, in the engine's key order.
std::string asked_settings_text(const engines::RunOptions& options);

}  // namespace impactbench::compare
