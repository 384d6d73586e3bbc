#include "common/registered_main.hpp"

#include <benchmark/benchmark.h>

namespace impactbench::bench {

int run_registered_benchmarks(int argc, char** argv, const std::function<void()>& register_all) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace impactbench::bench
