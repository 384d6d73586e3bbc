#pragma once
// The main() of the benchmarks that register their cases at run time (the problem sizes and
// files are only known then): register, then run as Google Benchmark's own main would.
#include <functional>
#include <string>

namespace impactbench::bench {

/// Calls `register_all`, then parses the benchmark flags (an unknown one is an error, exit 1)
/// and runs the selected benchmarks. An exception (a missing data folder, a bad problem file)
/// is printed as one line and returns 1.
int run_registered_benchmarks(int argc, char** argv, const std::function<void()>& register_all);

}  // namespace impactbench::bench
