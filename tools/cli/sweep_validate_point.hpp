#pragma once
// A point of a [validate] sweep: `impactbench validate --engines ENGINE --tosses T
// --initial-state S --set NAME=VALUE...` run in the worker, its result the counts of scored and
// failed tosses and, per score (docs/real-tosses.md), the mean, median and 90th percentile over
// the scored tosses (`position_mean`, ...). A fit of contact parameters is such a sweep over
// grid.set on the training split (docs/sweeps.md).
#include <string>

#include "tools/cli/sweep_prepared_point.hpp"

namespace impactbench::cli {

/// cube_toss with the point's parameters, checked (a state parameter cannot be swept: it comes
/// from each toss; the engine must be built and listed), and the settings text of the point
/// (prepare_point adds the hash). Throws CliError or ScenarioError.
PreparedPoint prepare_validate_point(const SweepSpec& spec, const SweepPoint& point);

/// Runs the validation; a point whose every toss failed is a failed result with the first
/// reason. `cpu_seconds` is the process CPU time of the whole validation.
PointResult run_validate_point(const SweepSpec& spec, const SweepPoint& point,
                               const PreparedPoint& prepared);

}  // namespace impactbench::cli
