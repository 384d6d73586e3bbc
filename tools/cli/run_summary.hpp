#pragma once
#include <iosfwd>

#include "lib/engines/run_result.hpp"

namespace impactbench::cli {

/// The end-of-run summary on stdout: every setting in force with its source ("setting
/// tolerance 1e-4 (command line)"), then the run's cost and convergence figures
/// (metrics::run_figures, the names of metrics.csv), events by kind, max penetration, energy at
/// start and end; numbers as output::number_text, read back exactly.
void print_run_summary(const scenario::Scenario& scenario, const engines::RunOptions& options,
                       const engines::RunResult& result);

}  // namespace impactbench::cli
