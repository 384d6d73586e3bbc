// A bad sweep file is refused with `path:line: field: what` and exit 1 before any point runs
// (the output folder is not even created); usage errors exit 2.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using impactbench::test_support::run_program;
using impactbench::test_support::TemporaryDirectory;

struct BadSpec {
  const char* name;
  const char* text;
  const char* message;  ///< what stderr must hold after "impactbench: <path>"
};

const std::string kHead = "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n";

class SweepRefusals : public ::testing::TestWithParam<BadSpec> {};

TEST_P(SweepRefusals, RefusedWithLineAndFieldBeforeAnyPointRuns) {
  TemporaryDirectory work("impactbench_sweep_bad");
  TemporaryDirectory capture("impactbench_capture");
  const fs::path spec = work.path() / "bad.toml";
  std::ofstream(spec) << GetParam().text;
  const fs::path dir = work.path() / "out";
  const auto outcome =
      run_program(IMPACTBENCH_CLI, "sweep '" + spec.string() + "' --out '" + dir.string() + "'",
                  capture.path());
  EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
  EXPECT_EQ(outcome.err.rfind("impactbench: " + spec.string() + GetParam().message, 0), 0u)
      << outcome.err;
  EXPECT_FALSE(fs::exists(dir));
}

INSTANTIATE_TEST_SUITE_P(
    Sweep, SweepRefusals,
    ::testing::Values(
        BadSpec{"UnknownScenario",
                "scenarios = [\"bouncing_ball\", \"nope\"]\nengines = [\"moreau\"]\n",
                ":1: scenarios[1]: "},
        BadSpec{"UnknownEngine", "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\", \"x\"]\n",
                ":2: engines[1]: unknown engine 'x'"},
        BadSpec{"UnknownKey",
                "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\ncolour = 1\n",
                ":3: colour: is not a key of a sweep file"},
        BadSpec{"UnknownGridKey",
                "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n[grid]\nstep = [1]\n",
                ":4: grid.step: is not a key of [grid]"},
        BadSpec{"EmptyGrid",
                "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n[grid]\ndt = []\n",
                ":4: grid.dt: is an empty grid"},
        BadSpec{
            "NegativeStep",
            "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n[grid]\ndt = [1e-3, -1]\n",
            ":4: grid.dt[1]: needs a positive number"},
        BadSpec{"BadParameterValue",
                "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n[grid.set]\n"
                "restitution = [0.5,\n 7]\n",
                ":5: grid.set.restitution[1]: "},
        BadSpec{"UnknownParameter",
                "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n[grid.set]\nnope = [1]\n",
                ":4: grid.set.nope[0]: "},
        BadSpec{"BadOptionValue",
                "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n[grid.option]\n"
                "\"moreau.theta\" = [0.5, \"x\"]\n",
                ":4: grid.option.moreau.theta[1]: moreau: setting 'theta' must be"},
        BadSpec{"OptionOfAnEngineNotSwept",
                "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n[grid.option]\n"
                "\"box2d.velocity_iterations\" = [8]\n",
                ":4: grid.option.box2d.velocity_iterations: needs the form"},
        BadSpec{
            "UnknownSolver",
            "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n[grid]\nsolver = [\"nsgs\", "
            "\"bogus\"]\n",
            ":4: grid.solver[1]: moreau: setting 'solver' must be one of"},
        BadSpec{"UnknownSettingsSet",
                "scenarios = [\"bouncing_ball\"]\nengines = [\"bullet\"]\n[grid]\nsettings = "
                "[\"default\",\n \"tuned\"]\n",
                ":5: grid.settings[1]: unknown settings set 'tuned'"},
        BadSpec{"SettingsSetNoEngineHas",
                "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n[grid]\nsettings = "
                "[\"expert\"]\n",
                ":4: grid.settings: none of the engines swept uses it"},
        BadSpec{"ValidateAnotherScenario",
                "scenarios = [\"cube_toss\", \"bouncing_ball\"]\nengines = [\"moreau\"]\n"
                "[validate]\n",
                ":1: scenarios[1]: a [validate] sweep runs cube_toss only, not 'bouncing_ball'"},
        BadSpec{"ValidateWithAStepAxis",
                "scenarios = [\"cube_toss\"]\nengines = [\"moreau\"]\n[validate]\n[grid]\n"
                "dt = [1e-3]\n",
                ":5: grid.dt: a [validate] sweep takes grid.set and grid.option only"},
        BadSpec{"ValidateBadTosses",
                "scenarios = [\"cube_toss\"]\nengines = [\"moreau\"]\n[validate]\n"
                "tosses = \"odd\"\n",
                ":4: validate.tosses: "},
        BadSpec{"ValidateBadInitialState",
                "scenarios = [\"cube_toss\"]\nengines = [\"moreau\"]\n[validate]\n"
                "initial_state = \"guess\"\n",
                ":4: validate.initial_state: needs sample or fit, not 'guess'"},
        BadSpec{"ValidateUnknownKey",
                "scenarios = [\"cube_toss\"]\nengines = [\"moreau\"]\n[validate]\nsplit = 1\n",
                ":4: validate.split: is not a key of [validate]"},
        BadSpec{"ValidateDataNotAFolder",
                "scenarios = [\"cube_toss\"]\nengines = [\"moreau\"]\n[validate]\n"
                "data = \"nowhere\"\n",
                ":3: validate.data: "},
        BadSpec{"ValidateSelectsNoToss",
                "scenarios = [\"cube_toss\"]\nengines = [\"moreau\"]\n[validate]\n"
                "tosses = \"100000\"\n",
                ":3: validate.tosses: selects no toss file"},
        BadSpec{"ValidateSweepsAStateParameter",
                "scenarios = [\"cube_toss\"]\nengines = [\"moreau\"]\n[validate]\n"
                "[grid.set]\nvx = [1, 2]\n",
                ":5: grid.set.vx[0]: the initial state comes from each toss; it cannot be "
                "swept"},
        BadSpec{
            "BillionPoints",
            "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\n[grid.set]\n"
            "a = [1,2,3,4,5,6,7,8,9,10]\nb = [1,2,3,4,5,6,7,8,9,10]\nc = [1,2,3,4,5,6,7,8,9,10]\n"
            "d = [1,2,3,4,5,6,7,8,9,10]\ne = [1,2,3,4,5,6,7,8,9,10]\nf = [1,2,3,4,5,6,7,8,9,10]\n"
            "g = [1,2,3,4,5,6,7,8,9,10]\nh = [1,2,3,4,5,6,7,8,9,10]\ni = [1,2,3,4,5,6,7,8,9,10]\n"
            "[grid]\ndt = [1e-3]\n",
            ":13: grid: expands to 1e9 points, more than 100000 (give --force to run them)"},
        BadSpec{"Syntax", "scenarios = [\"bouncing_ball\"\nengines = [\"moreau\"]\n",
                ":2: syntax: "}),
    [](const auto& test) { return std::string(test.param.name); });

TEST(SweepUsage, UsageErrorsExitTwo) {
  TemporaryDirectory work("impactbench_sweep_usage");
  TemporaryDirectory capture("impactbench_capture");
  const fs::path spec = work.path() / "s.toml";
  std::ofstream(spec) << kHead;
  for (const std::string& args :
       {"sweep '" + spec.string() + "'", "sweep '" + spec.string() + "' --out d --jobs 0",
        "sweep '" + spec.string() + "' --out d --executor pbs",
        "sweep '" + spec.string() + "' --out d --shard 3/2"}) {
    const auto outcome = run_program(IMPACTBENCH_CLI, args, capture.path(), "", work.path());
    EXPECT_EQ(outcome.exit_code, 2) << args << "\n" << outcome.err;
  }
  EXPECT_FALSE(fs::exists(work.path() / "d" / "points"));
}

}  // namespace
