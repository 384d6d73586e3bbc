// The suite's "Real tosses" section in its quick form: every built engine cube_toss lists
// scores each of the first 10 test tosses (odd numbers) or counts it as failed with its reason,
// none dropped; per_toss.csv holds one row per engine and toss, and the section's headings sit
// one level under the suite's title.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/csv_table.hpp"
#include "tools/cli/suite_real_tosses.hpp"
#include "tools/cli/validation_study.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

TEST(SuiteRealTosses, EveryEngineAccountsForEachOfTheFirstTenTestTosses) {
  const test_support::TemporaryDirectory work("impactbench_suite_tosses");
  const std::string section = cli::real_tosses_section(true, work.path());
  EXPECT_EQ(section.rfind("## Real tosses", 0), 0u) << section.substr(0, 80);
  EXPECT_NE(section.find("tosses `test (the first 10, --quick)`"), std::string::npos) << section;
  const auto engines = cli::cube_toss_engines(scenario::load_scenario_by_name("cube_toss"));
  ASSERT_GE(engines.size(), 5u);  // moreau, event, bullet, ode, mujoco (Siconos when built)
  for (const std::string& engine : engines) {
    const std::string row = "\n| " + engine + " | ";
    const auto at = section.find(row);
    ASSERT_NE(at, std::string::npos) << engine;
    const auto scored = std::stoi(section.substr(at + row.size()));
    const auto failed = std::stoi(section.substr(section.find(" | ", at + row.size()) + 3));
    EXPECT_EQ(scored + failed, 10) << engine;
  }
  const auto per_toss = test_support::read_csv_table(work.path() / "per_toss.csv");
  EXPECT_EQ(per_toss.rows.size(), 10 * engines.size());
  std::ifstream summary(work.path() / "summary.md");
  EXPECT_TRUE(summary.good());
}

}  // namespace
}  // namespace impactbench
