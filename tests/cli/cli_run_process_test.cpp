// Child processes of compare and suite: the files a child was writing are removed unless it
// finished, and an interrupt of impactbench reaches the child at once (it may sit in another
// process group, as under `timeout`) and ends the command with ProcessInterrupted.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tools/compare/run_process.hpp"

namespace impactbench::compare {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  return fs::temp_directory_path() /
         ("impactbench_run_process_" +
          std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name);
}

TEST(RunProcess, OutputOfAFailedChildIsRemovedAndOfASuccessfulOneKept) {
  const fs::path failed = scratch("failed.png"), done = scratch("done.png");
  EXPECT_EQ(run_process({"sh", "-c", "echo partial > '" + failed.string() + "'; exit 3"}, {failed}),
            3);
  EXPECT_FALSE(fs::exists(failed));
  EXPECT_EQ(run_process({"sh", "-c", "echo whole > '" + done.string() + "'"}, {done}), 0);
  EXPECT_TRUE(fs::exists(done));
  fs::remove(done);
}

TEST(RunProcess, InterruptStopsTheChildAtOnceAndRemovesItsOutput) {
  const fs::path partial = scratch("partial.json");
  const auto start = std::chrono::steady_clock::now();
  // The child writes half a file, interrupts its parent (as Ctrl-C would) and would then keep
  // running for 30 s in its own process group.
  EXPECT_THROW(run_process({"setsid", "sh", "-c",
                            "echo '{' > '" + partial.string() +
                                "'; kill -INT $PPID 2>/dev/null || kill -INT " +
                                std::to_string(::getpid()) + "; exec sleep 30"},
                           {partial}),
               ProcessInterrupted);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 10.0) << "the child was waited out instead of stopped";
  EXPECT_FALSE(fs::exists(partial));
}

}  // namespace
}  // namespace impactbench::compare
