#pragma once
// What one engine run cost and how well it solved its contact problems, under the names of the
// metrics.csv columns; `compare`, `suite` and the run summary of `run` all print these.
#include <string>
#include <utility>
#include <vector>

#include "lib/engines/run_result.hpp"

namespace impactbench::metrics {

/// engine_cpu_seconds, record_cpu_seconds, wall_seconds, steps, unconverged_steps (NaN when the
/// engine has no tolerance: RunResult::unconverged_note says why), mean_contacts, in this order.
std::vector<std::pair<std::string, double>> run_figures(const engines::RunResult& run);

}  // namespace impactbench::metrics
