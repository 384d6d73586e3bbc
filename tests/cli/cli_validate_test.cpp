// `impactbench validate` as a process: usage errors exit 2 and bad toss files exit 1, each as
// one line with nothing written; a free-fall toss is reproduced by the engines, and a toss that
// cannot be run is counted with its reason.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/csv_table.hpp"

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
    const Outcome outcome = run(
        "--engines mujoco --tosses 1-5 --no-plots --option mujoco.solref_timeconst=" + timeconst +
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
  EXPECT_FALSE(fs::exists(work_.path() / "out_0.05" / "error_over_time.png"));  // --no-plots
}

// --parameters FILE gives each engine its table's parameters and settings, under --set and
// --option: the same runs as the flags that say the same, to the last digit.
TEST_F(CliValidate, AParameterTableEqualsTheFlagsThatSayTheSame) {
  const fs::path table = work_.path() / "table.toml";
  std::ofstream(table)
      << "[mujoco]\nset = { friction = 0.5, restitution = 0.05 }\n"
      << "option = { solref_timeconst = 0.02 }\n[moreau]\nset = { friction = 0.1 }\n";
  const auto rows = [&](const std::string& name, const std::string& flags) {
    const fs::path out = work_.path() / name;
    const Outcome outcome =
        run("--tosses 1-5 --no-plots " + flags + " --out '" + out.string() + "'");
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    const std::string summary = read_text(out / "summary.md");
    return summary.substr(summary.find("| engine |"),
                          summary.find("\nFailed runs") - summary.find("| engine |"));
  };
  const std::string by_table = "--engines mujoco --parameters '" + table.string() + "'";
  EXPECT_EQ(rows("table", by_table),
            rows("flags",
                 "--engines mujoco --set friction=0.5 --set restitution=0.05 "
                 "--option mujoco.solref_timeconst=0.02"));
  EXPECT_EQ(
      rows("table_over", by_table + " --set friction=0.3 --option mujoco.solref_timeconst=0.01"),
      rows("flags_over",
           "--engines mujoco --set friction=0.3 --set restitution=0.05 "
           "--option mujoco.solref_timeconst=0.01"));
  // The shipped table names every engine validate runs by default.
  const Outcome fitted = run("--tosses 1 --no-plots --parameters fitted --out '" +
                             (work_.path() / "fitted").string() + "'");
  EXPECT_EQ(fitted.exit_code, 0) << fitted.err;
  EXPECT_NE(fitted.out.find("parameter set `fitted` (bullet: "), std::string::npos) << fitted.out;
}

TEST_F(CliValidate, BadParameterTablesExitOneNamingFileAndLine) {
  expect_failure(run("--parameters '" + (work_.path() / "none.toml").string() + "' --out '" +
                     out_.string() + "'"),
                 1, "none.toml: no such parameter file");
  struct Case {
    const char* table;
    const char* engines;
    const char* message;
  };
  const Case cases[] = {
      {"[moreau\nset = {}\n", "moreau", "table.toml:1: syntax:"},
      {"[warp]\nset = { friction = 0.2 }\n", "moreau", "table.toml:1: warp: is not an engine"},
      {"[moreau]\nsett = { friction = 0.2 }\n", "moreau",
       "table.toml:2: moreau.sett: is not a key (set, option)"},
      {"[moreau]\nset = { friction = 'high' }\n", "moreau",
       "table.toml:2: moreau.set.friction: needs a finite number"},
      {"[moreau]\nset = { z = 0.3 }\n", "moreau",
       "table.toml:2: moreau.set.z: is the initial state, which comes from each toss"},
      {"[moreau]\nset = 0.2\n", "moreau", "table.toml:2: moreau.set: needs a table, not a number"},
      {"[moreau]\nset = { frction = 0.2 }\n", "moreau",
       "table.toml: [moreau] set.frction: scenario 'cube_toss' has no parameter 'frction' (valid: "
       "g, side"},
      {"[moreau]\nset = { friction = -1 }\n", "moreau",
       "friction coefficient must be >= 0 (got -1)"},
      {"[mujoco]\noption = { solimp_dmin = 2 }\n", "mujoco",
       "table.toml: [mujoco]: mujoco: setting 'solimp_dmin' must be in (0, 1)"},
      {"[mujoco]\noption = { warp = 2 }\n", "mujoco",
       "table.toml: [mujoco]: mujoco: setting 'warp' is unknown"},
      {"[mujoco]\nset = { friction = 0.2 }\n", "moreau,mujoco", "no [moreau] table"},
      {"", "moreau", "table.toml: names no engine"},
  };
  const fs::path table = work_.path() / "table.toml";
  for (const Case& c : cases) {
    std::ofstream(table) << c.table;
    expect_failure(run(std::string("--engines ") + c.engines + " --tosses 1 --parameters '" +
                       table.string() + "' --out '" + out_.string() + "'"),
                   1, c.message);
  }
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
  for (const char* png : {"error_over_time.png", "error_distribution.png", "toss_trajectory.png"})
    EXPECT_GT(fs::file_size(out_ / png), 1000u) << png;
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

  // toss_trajectory.csv: the traced toss (the first, toss_001) as recorded, 16 rows, and each
  // engine's run at the same times; its z the free fall's.
  const auto trajectory = impactbench::test_support::read_csv_table(out_ / "toss_trajectory.csv");
  ASSERT_EQ(trajectory.rows.size(), 3 * 16u);
  for (std::size_t i = 0; i < trajectory.rows.size(); ++i) {
    const double t = std::stod(trajectory.at(i, "t"));
    EXPECT_EQ(trajectory.at(i, "source"), i < 16 ? "data" : i < 32 ? "mujoco" : "moreau");
    EXPECT_NEAR(std::stod(trajectory.at(i, "z")), 1.0 - 9.81 * t * t / 2, i < 16 ? 1e-15 : 1e-3);
  }
  // error_over_time.csv: per scored engine, 0.1 s of samples in bins of 0.02 s (6 bins, one
  // toss each); the toss's mean position error lies between its smallest and largest bin.
  const auto bins = impactbench::test_support::read_csv_table(out_ / "error_over_time.csv");
  ASSERT_EQ(bins.rows.size(), 12u);
  const auto per_toss = impactbench::test_support::read_csv_table(out_ / "per_toss.csv");
  for (std::size_t engine = 0; engine < 2; ++engine) {
    double low = 1e300, high = 0;
    for (std::size_t b = 6 * engine; b < 6 * engine + 6; ++b) {
      EXPECT_EQ(bins.at(b, "tosses"), "1");
      EXPECT_EQ(bins.at(b, "engine"), bins.at(6 * engine, "engine"));
      low = std::min(low, std::stod(bins.at(b, "position_mean")));
      high = std::max(high, std::stod(bins.at(b, "position_mean")));
    }
    for (std::size_t r = 0; r < per_toss.rows.size(); ++r)
      if (per_toss.at(r, "engine") == bins.at(6 * engine, "engine") &&
          per_toss.at(r, "status") == "scored") {
        EXPECT_LE(low, std::stod(per_toss.at(r, "position")));
        EXPECT_GE(high, std::stod(per_toss.at(r, "position")));
      }
  }
}

// Tosses 1, 5, 17 and 21 stopped the event-driven engine before: after an impact a corner's gap
// guard stayed at exactly zero, and CVODE would not go on from that root ("root found at and
// very near t"). Now each runs to its end and lies on a face: its centre at the rest height
// side/2 (the board at z = 0), which the engine's projection holds to its gap tolerance, 1e-9 m.
TEST_F(CliValidate, TheEventEngineRunsTossesWhoseGuardsStayAtZero) {
  for (const std::string number : {"1", "5", "17", "21"}) {
    const fs::path out = work_.path() / number;
    const Outcome outcome =
        run("--engines event --tosses " + number + " --no-plots --out '" + out.string() + "'");
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_NE(outcome.out.find("| event | 1 | 0 | position |"), std::string::npos) << outcome.out;
    const auto trajectory = impactbench::test_support::read_csv_table(out / "toss_trajectory.csv");
    ASSERT_EQ(trajectory.at(trajectory.rows.size() - 1, "source"), "event");
    EXPECT_NEAR(std::stod(trajectory.at(trajectory.rows.size() - 1, "z")), 0.1048 / 2, 1e-9)
        << number;
  }
}

TEST_F(CliValidate, ATracedTossMustBeSelected) {
  write_free_fall("toss_001.csv", 1.0, 0.0, 10);
  expect_failure(run("--trace-toss toss_009 " + data_and_out()), 2,
                 "--trace-toss toss_009: not among the selected tosses");
}

}  // namespace
