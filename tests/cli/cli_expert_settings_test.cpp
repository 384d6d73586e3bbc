// `--settings expert` through the program, as users run it: `compare` at the expert set runs on
// every shipped scenario for every reference engine the scenario lists (each run completes: no
// `failure` cell), our engines there run their defaults and say so, and an unknown set name is
// a usage error that writes nothing.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/csv_table.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace {

namespace fs = std::filesystem;
using impactbench::test_support::CliOutcome;
using impactbench::test_support::read_csv_table;
using impactbench::test_support::run_program;
using impactbench::test_support::TemporaryDirectory;

// Scenario × engine pairs that cannot run at the expert set, with the reason (also in
// docs/reference-engines.md#expert-settings). None: every pair runs.
const std::map<std::pair<std::string, std::string>, std::string> kCannotRun = {};

// The reference engines with an expert set that are built and listed by the scenario.
std::vector<std::string> expert_engines(const impactbench::scenario::Scenario& s) {
  std::vector<std::string> names;
  for (const auto& info : impactbench::adapters::engine_registry())
    if (info.run && !info.settings->expert.empty() && s.supports_engine(info.name) &&
        !kCannotRun.count({s.name, info.name}))
      names.push_back(info.name);
  return names;
}

std::string comma_list(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ",") + name;
  return text;
}

TEST(ExpertCompare, RunsEveryShippedScenarioForEveryReferenceEngine) {
  // Siconos has no expert set (it runs our own model, at its defaults); where it is not built
  // it is not among the registry's runnable engines either.
  const TemporaryDirectory work("impactbench_expert_compare");
  std::size_t pairs = 0;
  for (const std::string& name : impactbench::scenario::list_scenarios()) {
    SCOPED_TRACE(name);
    const auto s = impactbench::scenario::load_scenario_by_name(name);
    const std::vector<std::string> engines = expert_engines(s);
    ASSERT_FALSE(engines.empty()) << "no reference engine lists " << name;
    const fs::path dir = work.path() / name;
    const CliOutcome outcome = run_program(IMPACTBENCH_CLI,
                                           "compare " + name + " --engines " + comma_list(engines) +
                                               " --settings expert --duration 0.05 --no-plots "
                                               "--out '" +
                                               dir.string() + "'",
                                           work.path());
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    const auto table = read_csv_table(dir / "metrics.csv");
    ASSERT_EQ(table.rows.size(), engines.size()) << outcome.err;
    for (std::size_t r = 0; r < engines.size(); ++r) {
      EXPECT_EQ(table.at(r, "engine"), engines[r] + " (expert)");
      EXPECT_EQ(table.at(r, "failure"), "") << engines[r];
      // Every step of the scenario's own dt (no engine-specific step in the scenarios).
      EXPECT_EQ(table.at(r, "steps"), std::to_string(std::llround(0.05 / s.dt))) << engines[r];
      EXPECT_NE(table.at(r, "settings").find("(expert)"), std::string::npos) << engines[r];
      EXPECT_TRUE(fs::exists(dir / (engines[r] + "_expert_trajectory.csv"))) << engines[r];
      ++pairs;
    }
  }
  // 11 scenarios: Box2D lists the 8 planar ones, Bullet, ODE and MuJoCo all 11.
  EXPECT_EQ(pairs, 41u);
}

TEST(ExpertCompare, OurEnginesRunTheirDefaultsAndSaySo) {
  const TemporaryDirectory work("impactbench_expert_ours");
  const fs::path dir = work.path() / "cmp";
  const CliOutcome outcome = run_program(IMPACTBENCH_CLI,
                                         "compare sliding_block --engines moreau,box2d "
                                         "--settings expert --duration 0.05 --no-plots --out '" +
                                             dir.string() + "'",
                                         work.path());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto table = read_csv_table(dir / "metrics.csv");
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.at(0, "engine"), "moreau");
  EXPECT_EQ(table.at(0, "note"), "no expert settings set: its defaults");
  EXPECT_EQ(table.at(0, "settings").find("(expert)"), std::string::npos);
  EXPECT_NE(table.at(0, "settings").find("max_iterations=1000 (default)"), std::string::npos);
  EXPECT_EQ(table.at(1, "engine"), "box2d (expert)");
  EXPECT_NE(table.at(1, "settings").find("velocity_iterations=50 (expert)"), std::string::npos);
  EXPECT_NE(outcome.out.find("box2d (expert)"), std::string::npos) << outcome.out;
}

TEST(ExpertRun, SummaryMarksTheSetsValuesAndSaysWhenThereIsNone) {
  const TemporaryDirectory work("impactbench_expert_run");
  const CliOutcome bullet = run_program(IMPACTBENCH_CLI,
                                        "run bouncing_ball --engine bullet --settings expert "
                                        "--option erp=0.3 --duration 0.05 --out '" +
                                            (work.path() / "b.csv").string() + "'",
                                        work.path());
  ASSERT_EQ(bullet.exit_code, 0) << bullet.err;
  EXPECT_NE(bullet.out.find("  setting solver_iterations 20 (expert)\n"), std::string::npos)
      << bullet.out;
  EXPECT_NE(bullet.out.find("  setting erp 0.3 (command line)\n"), std::string::npos);
  EXPECT_NE(bullet.out.find("  setting dt 0.001 (scenario)\n"), std::string::npos);
  EXPECT_NE(bullet.out.find("  settings set expert: the values marked (expert) come from it\n"),
            std::string::npos);
  const CliOutcome event = run_program(IMPACTBENCH_CLI,
                                       "run bouncing_ball --engine event --settings expert "
                                       "--duration 0.05 --out '" +
                                           (work.path() / "e.csv").string() + "'",
                                       work.path());
  ASSERT_EQ(event.exit_code, 0) << event.err;
  EXPECT_NE(event.out.find("  settings set expert: event has none; its defaults are in force\n"),
            std::string::npos)
      << event.out;
  EXPECT_EQ(event.out.find("(expert)"), std::string::npos);
}

TEST(ExpertRun, UnknownSetIsAUsageErrorThatWritesNothing) {
  const TemporaryDirectory work("impactbench_expert_unknown");
  const fs::path csv = work.path() / "t.csv";
  const CliOutcome run = run_program(
      IMPACTBENCH_CLI,
      "run bouncing_ball --engine box2d --settings experts --out '" + csv.string() + "'",
      work.path());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err,
            "impactbench: --settings: unknown settings set 'experts' (sets: default or expert) "
            "(see --help)\n");
  EXPECT_EQ(run.out, "");
  EXPECT_FALSE(fs::exists(csv));
  const fs::path dir = work.path() / "cmp";
  const CliOutcome compare = run_program(
      IMPACTBENCH_CLI, "compare bouncing_ball --settings Expert --out '" + dir.string() + "'",
      work.path());
  EXPECT_EQ(compare.exit_code, 2);
  EXPECT_EQ(std::count(compare.err.begin(), compare.err.end(), '\n'), 1) << compare.err;
  EXPECT_NE(compare.err.find("unknown settings set 'Expert'"), std::string::npos) << compare.err;
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
