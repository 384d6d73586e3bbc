// The suite's "Real tosses" section in its quick form: at the default and at the fitted
// parameters, every built engine cube_toss lists scores each of the first 10 test tosses (odd
// numbers) or counts it as failed with its reason, none dropped; each set's per_toss.csv holds
// one row per engine and toss.
#include <fstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/csv_table.hpp"
#include "tools/cli/suite_real_tosses.hpp"
#include "tools/cli/validation_study.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

TEST(SuiteRealTosses, EveryEngineAccountsForEachOfTheFirstTenTestTossesAtBothParameterSets) {
  const test_support::TemporaryDirectory work("impactbench_suite_tosses");
  const std::string section = cli::real_tosses_section(true, work.path(), false);
  EXPECT_EQ(section.rfind("## Real tosses\n", 0), 0u) << section.substr(0, 80);
  const auto engines = cli::cube_toss_engines(scenario::load_scenario_by_name("cube_toss"));
  ASSERT_GE(engines.size(), 5u);  // moreau, event, bullet, ode, mujoco (Siconos when built)
  const auto fitted_at =
      section.find("### Real tosses: engines against the recordings, parameter set fitted");
  ASSERT_NE(fitted_at, std::string::npos) << section;
  for (const auto& [set, part] :
       {std::pair<std::string, std::string>{"default", section.substr(0, fitted_at)},
        std::pair<std::string, std::string>{"fitted", section.substr(fitted_at)}}) {
    EXPECT_NE(part.find("tosses `test (the first 10, --quick)`"), std::string::npos) << part;
    for (const std::string& engine : engines) {
      const std::string row = "\n| " + engine + " | ";
      const auto at = part.find(row);
      ASSERT_NE(at, std::string::npos) << set << " " << engine;
      const auto scored = std::stoi(part.substr(at + row.size()));
      const auto failed = std::stoi(part.substr(part.find(" | ", at + row.size()) + 3));
      EXPECT_EQ(scored + failed, 10) << set << " " << engine;
    }
    const auto per_toss = test_support::read_csv_table(work.path() / set / "per_toss.csv");
    EXPECT_EQ(per_toss.rows.size(), 10 * engines.size()) << set;
    std::ifstream summary(work.path() / set / "summary.md");
    EXPECT_TRUE(summary.good()) << set;
  }
}

}  // namespace
}  // namespace impactbench
