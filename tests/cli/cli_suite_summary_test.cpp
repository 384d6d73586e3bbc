// The suite summary's benchmark section names the folder it searched, or says that the build has
// no benchmark binaries; it never prints an empty path ("found in ." or "binaries in /").
#include <gtest/gtest.h>

#include "tools/compare/benchmark_section.hpp"

namespace impactbench::compare {
namespace {

TEST(SuiteSummary, ABuildWithoutBenchmarksSaysSo) {
  const std::string md = benchmarks_markdown({}, {});
  EXPECT_NE(md.find("This build has no benchmark binaries"), std::string::npos) << md;
  EXPECT_EQ(md.find("\"\""), std::string::npos) << md;
  EXPECT_EQ(md.find("binaries in "), std::string::npos) << md;
}

TEST(SuiteSummary, AnEmptyBenchmarkFolderIsNamed) {
  const std::string md = benchmarks_markdown("/opt/ib/libexec/impactbench", {});
  EXPECT_NE(md.find("No benchmark binaries found in /opt/ib/libexec/impactbench.\n"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("run the binaries in /opt/ib/libexec/impactbench (docs/performance.md)"),
            std::string::npos)
      << md;
}

TEST(SuiteSummary, EachBenchmarkHasItsCsvOrItsFailure) {
  const std::string md = benchmarks_markdown(
      "/b", {{"lcp_bench", "bench/lcp_bench.csv", ""}, {"event_bench", "", "timed out"}});
  EXPECT_NE(md.find("- lcp_bench: [bench/lcp_bench.csv](bench/lcp_bench.csv)\n"), std::string::npos)
      << md;
  EXPECT_NE(md.find("- event_bench: **failed** timed out\n"), std::string::npos) << md;
}

}  // namespace
}  // namespace impactbench::compare
