// The worker pool's folders when pools share an output folder (the shards of a Slurm array):
// a shared pool leaves logs/ and scratch/ in place, since a shard that removed them on ending
// pulled them from under another shard's worker about to open its log, and that point was lost
// (CI, stop 34); an exclusive pool removes them when empty; a worker that cannot open its log
// says so on the pool's stderr, and its point is counted lost.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tools/cli/sweep_pool.hpp"

namespace {

namespace fs = std::filesystem;
using impactbench::cli::PoolOptions;
using impactbench::cli::PoolPoint;
using impactbench::cli::run_pool;
using impactbench::test_support::TemporaryDirectory;

// A point whose worker writes no result and exits 0: the pool counts it as ran.
PoolPoint idle_point(const std::string& id) {
  return {id, "hash", [] {}};
}

TEST(SweepPool, ASharedPoolLeavesTheFoldersOtherShardsWriteIn) {
  const TemporaryDirectory work("impactbench_pool_shared");
  PoolOptions options;
  options.dir = work.path();
  options.shared = true;
  const auto outcome = run_pool({idle_point("0123456789abcdef")}, options);
  EXPECT_EQ(outcome.ran, 1u);
  EXPECT_EQ(outcome.lost, 0u);
  EXPECT_TRUE(fs::is_directory(work.path() / "logs"));
}

TEST(SweepPool, AnExclusivePoolRemovesItsEmptyFolders) {
  const TemporaryDirectory work("impactbench_pool_exclusive");
  PoolOptions options;
  options.dir = work.path();
  const auto outcome = run_pool({idle_point("0123456789abcdef")}, options);
  EXPECT_EQ(outcome.ran, 1u);
  EXPECT_FALSE(fs::exists(work.path() / "logs"));
  EXPECT_FALSE(fs::exists(work.path() / "scratch"));
}

TEST(SweepPool, AWorkerThatCannotOpenItsLogSaysWhyAndIsCountedLost) {
  const TemporaryDirectory work("impactbench_pool_no_log");
  const std::string id = "fedcba9876543210";
  fs::create_directories(work.path() / "logs" / (id + ".log"));  // a folder where the log goes
  PoolOptions options;
  options.dir = work.path();
  testing::internal::CaptureStderr();
  const auto outcome = run_pool({idle_point(id)}, options);
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_EQ(outcome.ran, 0u);
  EXPECT_EQ(outcome.lost, 1u);
  EXPECT_NE(said.find("sweep: cannot write the log " + (work.path() / "logs" / id).string() +
                      ".log of point " + id + ": Is a directory"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("the worker of point " + id + " exited with code 1"), std::string::npos)
      << said;
}

}  // namespace
