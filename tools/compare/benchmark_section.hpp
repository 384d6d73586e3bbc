#pragma once
// The suite summary's section on the benchmark binaries: one line per short benchmark run
// (its CSV, or why it failed), and where the full benchmarks are. A build without benchmark
// binaries (the `tests` preset) says so instead of naming an empty folder.
#include <filesystem>
#include <string>
#include <vector>

namespace impactbench::compare {

struct BenchmarkOutcome {
  std::string name, csv, failure;  ///< failure empty: the run wrote `csv`
};

/// `bench_dir`: where the suite looked for the binaries (empty: the build has none).
std::string benchmarks_markdown(const std::filesystem::path& bench_dir,
                                const std::vector<BenchmarkOutcome>& benchmarks);

}  // namespace impactbench::compare
