// `impactbench validate` as a process: usage errors exit 2 and bad toss files exit 1, each as
// one line with nothing written; a free-fall toss is reproduced by the engines, and a toss that
// cannot be run is counted with its reason.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using Outcome = impactbench::test_support::CliOutcome;
using impactbench::test_support::read_text;

class CliValidate : public ::testing::Test {
 protected:
  Outcome run(const std::string& arguments) const {
    return impactbench::test_support::run_program(IMPACTBENCH_CLI, "validate " + arguments,
                                                  capture_.path(), "");
  }

  /// A toss file in the data folder: a cube released level at height z0 with velocity
  /// (1, 0, vz0) and spin ω about z, `rows` samples at 148 Hz of its exact free flight.
  void write_free_fall(const std::string& name, double z0, double vz0, int rows) const {
    std::ofstream out(data_ / name);
    out.precision(17);
    out << "t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n";
    const double g = 9.81, omega = 2.0;
    for (int k = 0; k < rows; ++k) {
      const double t = k / 148.0;
      out << t << ',' << t << ",0," << z0 + vz0 * t - g * t * t / 2 << ','
          << std::cos(omega * t / 2) << ",0,0," << std::sin(omega * t / 2) << ",1,0," << vz0 - g * t
          << ",0,0," << omega << '\n';
    }
  }

  void expect_failure(const Outcome& outcome, int exit_code, const std::string& message) const {
    EXPECT_EQ(outcome.exit_code, exit_code) << outcome.err;
    EXPECT_TRUE(outcome.out.empty()) << outcome.out;
    EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << outcome.err;  // one line
    EXPECT_NE(outcome.err.find(message), std::string::npos) << outcome.err;
    EXPECT_FALSE(fs::exists(out_)) << "a failed validate left its output folder";
  }

  std::string data_and_out() const {
    return "--data '" + data_.string() + "' --out '" + out_.string() + "'";
  }

  impactbench::test_support::TemporaryDirectory work_{"impactbench_validate"};
  impactbench::test_support::TemporaryDirectory capture_{"impactbench_capture"};
  const fs::path data_ = work_.path() / "data";
  const fs::path out_ = work_.path() / "out";
  void SetUp() override { fs::create_directories(data_); }
};

TEST_F(CliValidate, UsageErrorsExitTwoBeforeAnythingRuns) {
  write_free_fall("toss_001.csv", 1.0, 0.0, 10);
  expect_failure(run("--tosses odd " + data_and_out()), 2, "--tosses: 'odd' is not all");
  expect_failure(run("--engines moreau,warp " + data_and_out()), 2, "unknown engine 'warp'");
  expect_failure(run("--engines box2d " + data_and_out()), 2, "cube_toss does not list box2d");
  expect_failure(run("--initial-state guess " + data_and_out()), 2, "--initial-state");
  expect_failure(run("--set x=1 " + data_and_out()), 2,
                 "--set x: the initial state comes from each toss");
  expect_failure(
      run("--data '" + (work_.path() / "none").string() + "' --out '" + out_.string() + "'"), 2,
      "not a directory");
  expect_failure(run("--option solref_timeconst=0.01 " + data_and_out()), 2,
                 "--option 'solref_timeconst=...' must name its engine");
  expect_failure(run("--engines moreau --option mujoco.iterations=5 " + data_and_out()), 2,
                 "--option mujoco.iterations: the engine is not validated here");
  expect_failure(run("--engines mujoco --option mujoco.no_such_key=1 " + data_and_out()), 2,
                 "no_such_key");
  expect_failure(run("--engines mujoco --option mujoco.solref_timeconst=-1 " + data_and_out()), 2,
                 "solref_timeconst");
}

// An engine's option reaches its runs: MuJoCo's solref time constant sets how far a landing cube
// sinks into the board, so a toss that lands scores differently at 0.005 s and 0.05 s; the
// summary names the option.
TEST_F(CliValidate, AnEnginesOptionReachesItsRuns) {
  const auto position = [&](const std::string& timeconst) {
    const fs::path out = work_.path() / ("out_" + timeconst);
    const Outcome outcome =
        run("--engines mujoco --tosses 1-5 --option mujoco.solref_timeconst=" + timeconst +
            " --out '" + out.string() + "'");
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    const std::string summary = read_text(out / "summary.md");
    EXPECT_NE(summary.find("parameters `mujoco.solref_timeconst=" + timeconst + "`"),
              std::string::npos)
        << summary;
    const std::string row = "| mujoco | ";
    const auto at = summary.find(" | position | side | ", summary.find(row));
    return std::stod(summary.substr(at + std::string(" | position | side | ").size()));
  };
  EXPECT_NE(position("0.005"), position("0.05"));
}

TEST_F(CliValidate, BadTossFilesExitOneNamingFileAndLine) {
  write_free_fall("toss_001.csv", 1.0, 0.0, 10);
  std::ofstream(data_ / "toss_003.csv") << "t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n"
                                        << "0,0,0,1,1,0,0,0,0,0,0,0,0,0\n"
                                        << "0.1,0,nan,1,1,0,0,0,0,0,0,0,0,0\n";
  expect_failure(run("--tosses all " + data_and_out()), 1, "toss_003.csv:3: column y is nan");
  fs::remove(data_ / "toss_003.csv");
  std::ofstream(data_ / "toss_005.csv") << "t,x,y,z\n0,0,0,1\n";
  expect_failure(run("--tosses 5 " + data_and_out()), 1, "toss_005.csv:1: missing column 'qw'");
  expect_failure(run("--tosses 7 " + data_and_out()), 1, "no toss file");
}

TEST_F(CliValidate, FreeFallIsReproducedAndAnUnrunnableTossIsCounted) {
  // toss_001: 0.1 s of free fall from 1 m, far above the board: the engines' errors are those
  // of their time stepping, ½ g h t ≈ 5e-4 m at h = 1e-3 s, t = 0.1 s (0.5 % of a side).
  write_free_fall("toss_001.csv", 1.0, 0.0, 16);
  // toss_003: its lowest corner starts 7.6 mm above the board and is 0.8 mm above it at the
  // second sample (z = 0.06 − 1/148 − g/(2·148²)): one free-flight sample, the fit needs 3, so
  // the toss fails with that reason for each engine.
  write_free_fall("toss_003.csv", 0.06, -1.0, 16);
  const Outcome outcome =
      run("--engines mujoco,moreau --initial-state fit --tosses 1-3 " + data_and_out());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const std::string csv = read_text(out_ / "per_toss.csv");
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line,
            "engine,toss,status,position,rotation,velocity,angular_velocity,rest_position,"
            "rest_rotation,first_contact_time,wall_seconds,failure");
  int scored = 0, failed = 0;
  while (std::getline(lines, line)) {
    if (line.find(",toss_001,scored,") != std::string::npos) {
      ++scored;
      const double position = std::strtod(line.c_str() + line.find("scored,") + 7, nullptr);
      EXPECT_LT(position, 0.01) << line;
      EXPECT_GT(position, 0.0) << line;
    }
    if (line.find(",toss_003,failed,") != std::string::npos) {
      ++failed;
      EXPECT_NE(line.find("free-flight sample(s) before the first contact; a fit needs 3"),
                std::string::npos)
          << line;
    }
  }
  EXPECT_EQ(scored, 2);
  EXPECT_EQ(failed, 2);
  const std::string summary = read_text(out_ / "summary.md");
  EXPECT_NE(summary.find("| mujoco | 1 | 1 | position | side |"), std::string::npos) << summary;
  EXPECT_NE(summary.find("- moreau, toss_003: "), std::string::npos) << summary;
  EXPECT_EQ(outcome.out.rfind(summary, 0), 0u);  // the summary is printed too
}

}  // namespace
