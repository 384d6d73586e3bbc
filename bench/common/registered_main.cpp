#include "common/registered_main.hpp"

#include <cstdio>
#include <exception>
#include <filesystem>

#include <benchmark/benchmark.h>

namespace impactbench::bench {

int run_registered_benchmarks(int argc, char** argv, const std::function<void()>& register_all) {
  // A missing data folder or an unreadable problem file is one line and exit 1, not an abort.
  const std::string program = std::filesystem::path(argv[0]).filename().string();
  try {
    register_all();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: %s\n", program.c_str(), error.what());
    return 1;
  }
  return 0;
}

}  // namespace impactbench::bench
