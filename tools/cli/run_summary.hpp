#pragma once
#include <iosfwd>

#include "lib/engines/run_result.hpp"

namespace impactbench::cli {

/// The end-of-run summary on stdout: engine settings, the run's cost and convergence figures
/// (metrics::run_figures), events by kind, max penetration, energy at start and end.
void print_run_summary(const scenario::Scenario& scenario, const engines::RunResult& result);

}  // namespace impactbench::cli
