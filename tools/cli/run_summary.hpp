#pragma once
#include <iosfwd>

#include "lib/engines/run_result.hpp"

namespace impactbench::cli {

/// The end-of-run summary on stdout: engine settings, steps, events by kind, max penetration,
/// energy at start and end, solver failures, CPU time.
void print_run_summary(const scenario::Scenario& scenario, const engines::RunResult& result);

}  // namespace impactbench::cli
