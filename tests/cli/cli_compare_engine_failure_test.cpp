// One failing engine does not sink a comparison: `compare` writes metrics.csv with the failed
// engine's row (its reason in `failure`) beside the measured rows of the others, and exits 4.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using impactbench::test_support::read_text;

// The comma-separated fields of a line up to the first quoted one (the failure and settings
// texts may hold commas; the figures before them do not).
std::vector<std::string> leading_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',') && (field.empty() || field.front() != '"'))
    fields.push_back(field);
  return fields;
}

std::string line_starting(const std::string& text, const std::string& start) {
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(start, 0) == 0) return line;
  return "";
}

TEST(CompareEngineFailure, FailedEngineGetsItsRowAndTheOthersAreWritten) {
  impactbench::test_support::TemporaryDirectory work("impactbench_cmp_fail");
  impactbench::test_support::TemporaryDirectory capture("impactbench_capture");
  const fs::path dir = work.path() / "cmp";
  fs::create_directories(dir);
  // A file of an earlier comparison, which must not be left to pass for this run's.
  std::ofstream(dir / "moreau_trajectory.csv") << "t\n0\n";
  // One Gauss–Seidel sweep cannot solve the pyramid's first contact problem: Moreau–Jean stops
  // at t = 0 (on_failure = stop), while Box2D runs its 50 steps.
  const auto outcome = impactbench::test_support::run_program(
      IMPACTBENCH_CLI,
      "compare box_pyramid --engines moreau,box2d --option moreau.max_iterations=1 "
      "--duration 0.05 --no-plots --out '" +
          dir.string() + "'",
      capture.path());
  // Before, the command ended with exit 1 and wrote no metrics.csv.
  EXPECT_EQ(outcome.exit_code, 4) << outcome.err;
  EXPECT_NE(outcome.err.find("compare: moreau failed; its row in metrics.csv gives the reason"),
            std::string::npos)
      << outcome.err;
  const std::string metrics = read_text(dir / "metrics.csv");
  ASSERT_FALSE(metrics.empty()) << "no metrics.csv";
  const std::vector<std::string> header = leading_fields(metrics.substr(0, metrics.find('\n')));
  const auto steps_at = std::find(header.begin(), header.end(), "steps") - header.begin();
  ASSERT_LT(steps_at, static_cast<long>(header.size()));
  EXPECT_NE(metrics.find(",failure,note,settings\n"), std::string::npos) << metrics;

  const std::string moreau = line_starting(metrics, "moreau,");
  EXPECT_NE(moreau.find("max-iterations"), std::string::npos) << moreau;
  EXPECT_NE(moreau.find("max_iterations=1 (command line)"), std::string::npos) << moreau;
  EXPECT_EQ(leading_fields(moreau).at(static_cast<std::size_t>(steps_at)), "");  // no figures

  const std::string box2d = line_starting(metrics, "box2d,");
  EXPECT_EQ(leading_fields(box2d).at(static_cast<std::size_t>(steps_at)), "50") << box2d;
  EXPECT_TRUE(fs::exists(dir / "box2d_trajectory.csv"));
  EXPECT_FALSE(fs::exists(dir / "moreau_trajectory.csv"));
}

TEST(CompareEngineFailure, SuccessfulCompareExitsZeroWithEmptyFailures) {
  impactbench::test_support::TemporaryDirectory work("impactbench_cmp_ok");
  impactbench::test_support::TemporaryDirectory capture("impactbench_capture");
  const fs::path dir = work.path() / "cmp";
  const auto outcome = impactbench::test_support::run_program(
      IMPACTBENCH_CLI,
      "compare box_pyramid --engines moreau,box2d --duration 0.02 --no-plots --out '" +
          dir.string() + "'",
      capture.path());
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  const std::string metrics = read_text(dir / "metrics.csv");
  // failure, note: both empty for Moreau–Jean, which has a tolerance and ran.
  EXPECT_NE(line_starting(metrics, "moreau,").find(",,,duration="), std::string::npos) << metrics;
}

}  // namespace
