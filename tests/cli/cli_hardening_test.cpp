// The impactbench program on input that used to crash it, hang it or be accepted: each case
// must end with one line on stderr, the documented exit code and no file left behind; outputs
// written through special files and links leave those in place.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kScenarios = fs::path(IMPACTBENCH_TEST_DATA_DIR) / ".." / ".." / "scenarios";

using Outcome = impactbench::test_support::CliOutcome;
using impactbench::test_support::read_text;

class CliHardening : public ::testing::Test {
 protected:
  /// Runs `[environment] impactbench <arguments>` in the work directory, with a time limit.
  Outcome run(const std::string& arguments, const std::string& environment = "",
              int seconds = 60) const {
    return impactbench::test_support::run_program(IMPACTBENCH_CLI, arguments, capture_, environment,
                                                  directory_, seconds);
  }

  /// One line on stderr holding `message`, the exit code, nothing written to the directory
  /// except the files in `keep`.
  void expect_failure(const Outcome& outcome, int exit_code, const std::string& message,
                      std::size_t files_before = 0) const {
    EXPECT_EQ(outcome.exit_code, exit_code) << outcome.err;
    ASSERT_FALSE(outcome.err.empty());
    EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << outcome.err;
    EXPECT_EQ(outcome.err.rfind("impactbench: ", 0), 0u) << outcome.err;
    EXPECT_NE(outcome.err.find(message), std::string::npos) << outcome.err;
    EXPECT_EQ(file_count(), files_before) << "a failed run left a file";
  }

  std::size_t file_count() const {
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(directory_)) ++count;
    return count;
  }

  /// A copy of the scenarios folder in which `name`.toml has `from` replaced by `to`; returns
  /// the environment setting that points impactbench at it.
  std::string mutated_scenarios(const std::string& name, const std::string& from,
                                const std::string& to) const {
    const fs::path copy = capture_ / "scenarios";
    fs::create_directories(copy);
    for (const auto& entry : fs::directory_iterator(kScenarios))
      if (entry.path().extension() == ".toml")
        fs::copy_file(entry.path(), copy / entry.path().filename(),
                      fs::copy_options::overwrite_existing);
    std::string text = read_text(copy / (name + ".toml"));
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    std::ofstream(copy / (name + ".toml")) << text;
    return "IMPACTBENCH_SCENARIOS='" + copy.string() + "'";
  }

  impactbench::test_support::TemporaryDirectory work_{"impactbench_harden"};
  impactbench::test_support::TemporaryDirectory capture_directory_{"impactbench_capture"};
  const fs::path directory_ = work_.path();
  const fs::path capture_ = capture_directory_.path();
};

// --- crashes -------------------------------------------------------------------------------

TEST_F(CliHardening, Box2dRefusesValuesOutsideFloatRange) {
  struct Case {
    const char* arguments;
    const char* message;
  };
  for (const Case& c : {
           Case{"bouncing_ball --set mass=1e39", "mass = 1e39 kg"},
           Case{"bouncing_ball --set mass=1e-40", "mass = 1e-40 kg"},
           Case{"bouncing_ball --set height=1e39", "position = 1e39 m"},
           Case{"bouncing_ball --set radius=1e-25", "area = "},
           Case{"sliding_block --set v0=1e39", "velocity = 1e39 m/s"},
           Case{"disk_pile --set width=1e39", "position"},
       }) {
    SCOPED_TRACE(c.arguments);
    const Outcome outcome =
        run(std::string("run ") + c.arguments + " --engine box2d --out t.csv --duration 0.01");
    expect_failure(outcome, 1, c.message);
    EXPECT_NE(outcome.err.find("single precision"), std::string::npos) << outcome.err;
  }
}

TEST_F(CliHardening, EventEngineRefusesACradleWithoutBalls) {
  expect_failure(run("run newtons_cradle --engine event --set count=0 --out t.csv"), 1,
                 "bodies: no body to simulate");
}

TEST_F(CliHardening, SensitivityRefusesAContactSetThatChanges) {
  // Box-on-box contact features come and go along the run; the linearisation indexes them.
  // (box_pyramid does not list the event engine; the copy does, to reach the model.)
  const std::string environment =
      mutated_scenarios("box_pyramid", "engines = [\"moreau\", \"box2d\"",
                        "engines = [\"moreau\", \"event\", \"box2d\"");
  expect_failure(
      run("sensitivity box_pyramid --set rows=3 --duration 0.2 --out g.csv", environment), 1,
      "the linearisation needs a fixed contact set");
}

// --- hangs ---------------------------------------------------------------------------------

TEST_F(CliHardening, StepCountsThatCannotFitAreRefused) {
  // Steps are streamed, not kept: the bound is what a run could finish (1e12 steps).
  expect_failure(run("run bouncing_ball --engine moreau --dt 1e-9 --duration 1e4 --out t.csv"), 1,
                 "needs 1e13 steps; at most 1e12 are allowed");
  expect_failure(run("run bouncing_ball --engine moreau --dt 1e-300 --out t.csv"), 1,
                 "steps; at most 1e12 are allowed");
  expect_failure(run("run bouncing_ball --engine moreau --duration 1e308 --out t.csv"), 1,
                 "steps; at most 1e12 are allowed");
  expect_failure(run("run bouncing_ball --engine box2d --duration 1e10 --out t.csv"), 1,
                 "box2d: duration 1e10 s");
  expect_failure(run("run bouncing_ball --engine event --duration 1e308 --out t.csv"), 1,
                 "event: duration 1e308 s at output_interval");
}

TEST_F(CliHardening, ARunFailingAfterItsFirstRowsWereStreamedLeavesNoFile) {
  // An infinite force from t = 0.01: the rows of the first ten steps are already in the
  // temporary file when Moreau–Jean stops.
  const std::string environment =
      mutated_scenarios("incline", "force = \"push_rate*t\"",
                        "force = \"push_rate*t + (t > 0.01 && t < 0.04 ? 1e300*1e300 : 0)\"");
  expect_failure(run("run incline --engine moreau --out t.csv --events e.csv", environment), 1,
                 "input u(0.0105");
}

TEST_F(CliHardening, SampleIntervalWritesOneRowPerIntervalAndRefusesBadValues) {
  // 1 s at dt = 1 ms, one row per 0.1 s: t = 0, 0.1, ..., 1 (the last state is on the grid).
  const Outcome outcome =
      run("run bouncing_ball --engine moreau --duration 1 --sample-dt 0.1 --out t.csv");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const std::string text = read_text(directory_ / "t.csv");
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + 11) << text;
  EXPECT_NE(outcome.out.find("samples 11\n"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("steps                1000\n"), std::string::npos) << outcome.out;
  fs::remove(directory_ / "t.csv");
  for (const std::string bad : {"-1", "nan", "inf", "x"})
    expect_failure(run("run bouncing_ball --engine moreau --sample-dt " + bad + " --out t.csv"), 2,
                   "--sample-dt: must be a finite number >= 0");
}

TEST_F(CliHardening, ProgressIsShownWhenAskedAndNotOnAPipeOtherwise) {
  const Outcome quiet = run("run bouncing_ball --engine moreau --duration 0.1 --out t.csv");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");  // stderr is a file here, not a terminal
  const Outcome shown =
      run("run bouncing_ball --engine moreau --duration 0.1 --progress --out t.csv");
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_EQ(shown.err.rfind("\rmoreau on bouncing_ball: t = 0 of 0.1 s (0%), ", 0), 0u)
      << shown.err;
  EXPECT_EQ(shown.err.back(), '\n');  // the line is ended before the summary
}

TEST_F(CliHardening, EventEngineStopsOnANonFiniteInputForce) {
  // NaN between t = 0.01 and 0.04 only: the loader's checks at t = 0 and t = duration pass.
  const std::string environment =
      mutated_scenarios("incline", "force = \"push_rate*t\"",
                        "force = \"push_rate*t + (t > 0.01 && t < 0.04 ? sqrt(-1) : 0)\"");
  expect_failure(run("run incline --engine event --out t.csv", environment, 60), 1,
                 "input u(t) is not finite at t = ");
}

TEST_F(CliHardening, SensitivityRefusesAScenarioWithoutTheEventEngine) {
  expect_failure(run("sensitivity disk_pile --out g.csv"), 1,
                 "does not list (its engines: moreau, box2d, bullet, ode and mujoco)");
}

// --- accepted where it must refuse ---------------------------------------------------------

TEST_F(CliHardening, RunWhoseStateBlowsUpFailsAndWritesNothing) {
  expect_failure(run("run bouncing_ball --engine bullet --set mass=1e300 --out t.csv"), 1,
                 "bullet: the state became non-finite");
  // ODE's internal assertion (it aborts the process by default) fails the run the same way.
  expect_failure(run("run bouncing_ball --engine ode --set mass=1e300 --out t.csv"), 1,
                 "ode: internal error");
}

TEST_F(CliHardening, OutputThroughASymlinkReplacesTheFileItNames) {
  std::ofstream(directory_ / "target.csv") << "old\n";
  fs::create_symlink("target.csv", directory_ / "link.csv");
  const Outcome outcome = run("run bouncing_ball --engine moreau --duration 0.01 --out link.csv");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_TRUE(fs::is_symlink(directory_ / "link.csv"));
  EXPECT_EQ(read_text(directory_ / "target.csv").rfind("t,", 0), 0u);
}

TEST_F(CliHardening, OutputIntoAFifoWritesThroughIt) {
  ASSERT_EQ(::mkfifo((directory_ / "pipe").c_str(), 0600), 0);
  // A reader drains the pipe while impactbench writes into it.
  const std::string drained = (capture_ / "drained").string();
  const std::string reader = "cat '" + (directory_ / "pipe").string() + "' > '" + drained + "' &";
  const Outcome outcome =
      run("run bouncing_ball --engine moreau --duration 0.01 --out pipe", reader);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  struct stat status {};
  ASSERT_EQ(::lstat((directory_ / "pipe").c_str(), &status), 0);
  EXPECT_TRUE(S_ISFIFO(status.st_mode));
  ::sleep(1);
  EXPECT_EQ(read_text(drained).rfind("t,", 0), 0u);
}

TEST_F(CliHardening, OutputToDevNullLeavesItADevice) {
  const Outcome outcome = run("run bouncing_ball --engine moreau --duration 0.01 --out /dev/null");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  struct stat status {};
  ASSERT_EQ(::stat("/dev/null", &status), 0);
  EXPECT_TRUE(S_ISCHR(status.st_mode));
  EXPECT_EQ(file_count(), 0u);
}

TEST_F(CliHardening, TwoSpellingsOfOneOutputAreRefused) {
  fs::create_directory(directory_ / "o");
  expect_failure(
      run("run bouncing_ball --engine moreau --out o/t.csv --events o/./t.csv --duration 0.01"), 2,
      "--out and --events name the same file", 1);
}

TEST_F(CliHardening, SensitivityChecksItsPredictionPathBeforeWriting) {
  expect_failure(run("sensitivity bouncing_ball --duration 0.5 --out g.csv --prediction "
                     "nodir/p.csv"),
                 1, "--prediction nodir/p.csv: directory nodir does not exist");
  expect_failure(run("sensitivity bouncing_ball --duration 0.5 --out g.csv --prediction ./g.csv"),
                 2, "--out and --prediction name the same file");
}

TEST_F(CliHardening, BrokenEntryInTheScenariosFolderIsSkippedWithAWarning) {
  const fs::path folder = capture_ / "loop";
  fs::create_directories(folder);
  fs::copy_file(kScenarios / "bouncing_ball.toml", folder / "bouncing_ball.toml");
  fs::create_symlink("loop.toml", folder / "loop.toml");  // a link to itself
  const Outcome outcome =
      run("describe bouncing_ball", "IMPACTBENCH_SCENARIOS='" + folder.string() + "'");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("bouncing_ball"), std::string::npos);
  EXPECT_NE(outcome.err.find("warning: skipping"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("loop.toml"), std::string::npos) << outcome.err;
}

TEST_F(CliHardening, ZeroGravityRunsWhenTheDurationDoesNotNeedTheFallTime) {
  // bouncing_ball: t_first = sqrt(2 (h - r) / g) is infinite, duration = min(..., 60) is not.
  const Outcome outcome = run("run bouncing_ball --engine moreau --set g=0 --dt 0.01 --out t.csv");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
}

TEST_F(CliHardening, RestingBallNamesTheParameterThatMadeTheDurationZero) {
  expect_failure(run("run bouncing_ball --engine moreau --set height=0.1 --out t.csv"), 1,
                 "duration: must be > 0 (got 0) for --set height=0.1");
}

TEST_F(CliHardening, RestingBallRunsWhenTheUserGivesTheDuration) {
  // The run does not need the duration formula that vanishes for height = radius.
  const Outcome outcome = run(
      "run bouncing_ball --engine moreau --set height=0.1 --duration 0.05 --dt 0.01 --out t.csv");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_TRUE(fs::exists(directory_ / "t.csv"));
}

// --- messages and conventions --------------------------------------------------------------

TEST_F(CliHardening, NewOutputFollowsTheUmaskAndAnExistingFileKeepsItsMode) {
  const Outcome created =
      run("run bouncing_ball --engine moreau --duration 0.01 --out new.csv", "umask 022;");
  ASSERT_EQ(created.exit_code, 0) << created.err;
  EXPECT_EQ(fs::status(directory_ / "new.csv").permissions(),
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                fs::perms::others_read);
  std::ofstream(directory_ / "kept.csv") << "old\n";
  fs::permissions(directory_ / "kept.csv", fs::perms::owner_read | fs::perms::owner_write |
                                               fs::perms::group_read | fs::perms::group_write);
  const Outcome replaced =
      run("run bouncing_ball --engine moreau --duration 0.01 --out kept.csv", "umask 077;");
  ASSERT_EQ(replaced.exit_code, 0) << replaced.err;
  EXPECT_EQ(fs::status(directory_ / "kept.csv").permissions(),
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                fs::perms::group_write);
}

TEST_F(CliHardening, ControlCharactersInAFileAreEscapedInTheMessage) {
  // A TOML escape puts ESC (0x1b) into the engine name, which the message quotes.
  const std::string environment = mutated_scenarios("bouncing_ball", "engines = [\"moreau\"",
                                                    "engines = [\"moreau\\u001b[31m\"");
  const Outcome outcome = run("describe bouncing_ball", environment);
  EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
  EXPECT_EQ(outcome.err.find('\x1b'), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("unknown engine 'moreau\\x1b[31m'"), std::string::npos) << outcome.err;
  EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << outcome.err;
}

// --- second hardening pass ---------------------------------------------------------------

TEST_F(CliHardening, OutputToStdoutThatIsAPipeIsWrittenThrough) {
  // /dev/stdout → /proc/self/fd/1, whose link text for a pipe ("pipe:[N]") names no file.
  const std::string command = "cd '" + directory_.string() + "' && '" + IMPACTBENCH_CLI +
                              "' run bouncing_ball --engine moreau --duration 0.01 --out "
                              "/dev/stdout 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  char buffer[4096];
  for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    out.append(buffer, got);
  const int status = ::pclose(pipe);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  EXPECT_EQ(out.rfind("t,ball.x,ball.y,ball.theta,", 0), 0u) << out.substr(0, 200);
  EXPECT_EQ(file_count(), 0u);
}

TEST_F(CliHardening, AMalformedDurationInTheFileIsRefusedWithTheFlagToo) {
  const std::string environment =
      mutated_scenarios("bouncing_ball", "duration = ", "duration = 07:32:00\n# was: ");
  for (const std::string command :
       {"run bouncing_ball --engine moreau --duration 0.1 --out t.csv", "describe bouncing_ball"})
    expect_failure(run(command, environment), 1, "bouncing_ball.toml:");
}

TEST_F(CliHardening, ASolutionThatNamesTheProblemFileIsRefused) {
  const fs::path problem = directory_ / "p.lcp";
  fs::copy_file(fs::path(IMPACTBENCH_TEST_DATA_DIR) / "lcp" / "two_by_two.lcp", problem);
  const std::string before = read_text(problem);
  expect_failure(run("solve p.lcp --solver lemke --solution ./p.lcp"), 2,
                 "--solution ./p.lcp names the problem file", 1);
  EXPECT_EQ(read_text(problem), before);
}

TEST_F(CliHardening, CompareRefusesAnEngineNamedTwice) {
  expect_failure(run("compare bouncing_ball --engines moreau,moreau --no-plots --out o"), 2,
                 "engine 'moreau' is named twice in --engines");
}

TEST_F(CliHardening, CompareRefusesAnUnsupportedEngineBeforeRunningAny) {
  expect_failure(run("compare sphere_spin --engines moreau,box2d --no-plots --out o"), 1,
                 "scenario 'sphere_spin' cannot be run by engine 'box2d' (its engines: moreau, "
                 "event, bullet, ode, mujoco");
}

TEST_F(CliHardening, ASubnormalSampleIntervalIsRefusedNotOverflowed) {
  expect_failure(
      run("run bouncing_ball --engine moreau --duration 0.05 --sample-dt 5e-324 --out t.csv"), 2,
      "sample interval 5e-324 s needs");
}

TEST_F(CliHardening, ASubnormalStepIsRefusedAsAStepCount) {
  // std::stod refused 1e-310 (subnormal) with "stod"; it is a step no run could finish.
  expect_failure(run("run bouncing_ball --engine moreau --duration 0.05 --dt 1e-310 --out t.csv"),
                 1, "steps; at most 1e12 are allowed");
  expect_failure(
      run("run bouncing_ball --engine box2d --duration 0.05 --option dt=1e-310 --out t.csv"), 1,
      "steps; at most 1e12 are allowed");
  const std::string environment =
      mutated_scenarios("bouncing_ball", "dt = 1e-3\n", "dt = 1e-310\n");
  expect_failure(run("describe bouncing_ball", environment), 1,
                 "bouncing_ball.toml:8: dt: moreau: duration");
}

TEST_F(CliHardening, AScenarioToleranceOutOfTheEnginesRangeIsBadData) {
  const std::string environment =
      mutated_scenarios("bouncing_ball", "tolerance = 1e-10\n", "tolerance = 10\n");
  for (const std::string command :
       {"describe bouncing_ball", "run bouncing_ball --engine moreau --out t.csv"})
    expect_failure(run(command, environment), 1,
                   "bouncing_ball.toml:9: tolerance: moreau: must be in (0, 1], got '10'");
}

TEST_F(CliHardening, AFailedSecondOutputLeavesNoFirst) {
  // /dev/full takes the open and fails the write: the first file must not stay either.
  expect_failure(run("run bouncing_ball --engine moreau --duration 0.01 --out t.csv --events "
                     "/dev/full"),
                 1, "/dev/full");
  expect_failure(run("sensitivity bouncing_ball --duration 0.5 --out g.csv --prediction /dev/full"),
                 1, "/dev/full");
}

}  // namespace
