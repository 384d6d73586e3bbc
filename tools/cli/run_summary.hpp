#pragma once
#include <iosfwd>

#include "lib/engines/run_result.hpp"

namespace impactbench::cli {

/// The end-of-run summary on stdout: engine settings, steps, events by kind, max penetration,
/// energy at start and end, solver failures, CPU time.
/// Every setting in force with its source ("setting tolerance 1e-4 (command line)"), then what
/// the run did; numbers as output::number_text, read back exactly.
void print_run_summary(const scenario::Scenario& scenario, const engines::RunOptions& options,
                       const engines::RunResult& result);

}  // namespace impactbench::cli
