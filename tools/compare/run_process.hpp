#pragma once
#include <string>
#include <vector>

namespace impactbench::compare {

/// Runs argv[0] with the arguments (no shell) and waits; returns its exit status, or -1 when it
/// could not be started.
int run_process(const std::vector<std::string>& argv);

}  // namespace impactbench::compare
