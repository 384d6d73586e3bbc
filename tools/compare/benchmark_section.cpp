#include "tools/compare/benchmark_section.hpp"

#include <sstream>

namespace impactbench::compare {

std::string benchmarks_markdown(const std::filesystem::path& bench_dir,
                                const std::vector<BenchmarkOutcome>& benchmarks) {
  std::ostringstream md;
  md << "## Benchmarks (short versions)\n\n";
  if (bench_dir.empty()) {
    md << "This build has no benchmark binaries (the `release` preset builds them: "
          "`bash tools/run_suite.sh`).\n";
    return md.str();
  }
  if (benchmarks.empty()) md << "No benchmark binaries found in " << bench_dir.string() << ".\n";
  for (const auto& b : benchmarks)
    md << "- " << b.name << ": "
       << (b.failure.empty() ? "[" + b.csv + "](" + b.csv + ")" : "**failed** " + b.failure)
       << "\n";
  md << "\nThe full benchmarks: run the binaries in " << bench_dir.string()
     << " (docs/performance.md).\n";
  return md.str();
}

}  // namespace impactbench::compare
