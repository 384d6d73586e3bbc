#pragma once
// A run's positions as a signal for the trajectory errors: as the engine reports them (every
// engine builds the scenario's surfaces, Box2D's skin included, so no height is corrected).
#include "lib/engines/run_result.hpp"
#include "lib/metrics/trajectory_error.hpp"

namespace impactbench::metrics {

/// The samples' times and position vectors q, in the run's order.
Signal position_signal(const engines::RunResult& run);

}  // namespace impactbench::metrics
