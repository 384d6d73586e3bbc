// A run ended by a signal leaves no file behind: not its output, and not the temporary it was
// writing (an unnamed file, so even SIGKILL leaves nothing; a named fallback is removed on
// SIGINT and SIGTERM). Each case starts the program as a child, lets it stream rows for a
// while, signals it and inspects the output folder.
#include <signal.h>
#include <stdlib.h>  // setenv
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"

namespace impactbench {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> entries(const fs::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory))
    names.push_back(entry.path().filename().string());
  return names;
}

/// Starts a long run writing into `directory`, waits until it has run for a while, sends
/// `signal_number`; returns the child's wait status.
int interrupted_run(const fs::path& directory, int signal_number) {
  const std::string out = (directory / "t.csv").string();
  const std::string events = (directory / "ev.csv").string();
  const pid_t child = ::fork();
  if (child == 0) {
    // Every state of a 1e-5 s step over 1,000 s: the run is still writing when signalled.
    ::execl(IMPACTBENCH_CLI, IMPACTBENCH_CLI, "run", "bouncing_ball", "--engine", "moreau", "--dt",
            "1e-5", "--duration", "1000", "--sample-dt", "0", "--out", out.c_str(), "--events",
            events.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  ::kill(child, signal_number);
  int status = 0;
  ::waitpid(child, &status, 0);
  return status;
}

class InterruptedRun : public ::testing::TestWithParam<int> {};

TEST_P(InterruptedRun, LeavesNoFile) {
  const test_support::TemporaryDirectory directory("impactbench_interrupted");
  const int status = interrupted_run(directory.path(), GetParam());
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended by itself, status " << status;
  EXPECT_EQ(WTERMSIG(status), GetParam());
  EXPECT_EQ(entries(directory.path()), std::vector<std::string>{});
}

std::string signal_name(const ::testing::TestParamInfo<int>& signal) {
  return signal.param == SIGINT ? "SIGINT" : signal.param == SIGTERM ? "SIGTERM" : "SIGKILL";
}

INSTANTIATE_TEST_SUITE_P(Signals, InterruptedRun, ::testing::Values(SIGINT, SIGTERM, SIGKILL),
                         signal_name);

// Ctrl-C while the suite waits for a plot (here a stand-in interpreter that sleeps) ends the
// suite at once with a failure status, as it does during a benchmark.
TEST(InterruptedSuite, StopsDuringAPlot) {
  const test_support::TemporaryDirectory directory("impactbench_interrupted_suite");
  const fs::path marker = directory.path() / "plot_started";
  const fs::path python = directory.path() / "slow_python";
  {
    std::ofstream script(python);
    script << "#!/bin/sh\ntouch '" << marker.string() << "'\nexec sleep 120\n";
  }
  fs::permissions(python, fs::perms::owner_all);
  const std::string out = (directory.path() / "results").string();
  const pid_t child = ::fork();
  if (child == 0) {
    ::setenv("IMPACTBENCH_PYTHON", python.c_str(), 1);
    ::execl(IMPACTBENCH_CLI, IMPACTBENCH_CLI, "suite", "--quick", "--out", out.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto wait_for = [child](std::chrono::seconds limit, int& status) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < end) {
      if (::waitpid(child, &status, WNOHANG) == child) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  };
  int status = 0;
  const auto start = std::chrono::steady_clock::now();
  while (!fs::exists(marker) && std::chrono::steady_clock::now() - start < std::chrono::minutes(5))
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(fs::exists(marker)) << "the suite reached no plot within 5 minutes";
  ::kill(child, SIGINT);
  const bool ended = wait_for(std::chrono::seconds(20), status);
  if (!ended) {
    ::kill(child, SIGKILL);
    ::waitpid(child, &status, 0);
  }
  EXPECT_TRUE(ended) << "the suite went on after Ctrl-C";
  EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
}

}  // namespace
}  // namespace impactbench
