// The suite's work-precision points run as sweeps (the local executor, its forked workers): each
// point's error is the figure `compare` gives for that engine at that step or tolerance, failed
// points keep their reason, and the sweep files left in the suite's folder can be rerun by hand.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lib/output/number_text.hpp"
#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/csv_table.hpp"
#include "tools/cli/suite_work_precision.hpp"
#include "tools/compare/summary_format.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

namespace fs = std::filesystem;
using test_support::read_csv_table;
using test_support::run_program;
using test_support::TemporaryDirectory;

// The quick suite's points of a shipped scenario, run for `duration` (0: the scenario's own).
std::vector<compare::WorkPoint> sweep_points(const std::string& scenario_name, double duration,
                                             const std::string& quantity, const fs::path& dir,
                                             std::vector<std::string>& notes) {
  auto s = scenario::load_scenario_by_name(scenario_name);
  if (duration > 0) s.duration = duration;
  return cli::work_precision_by_sweep(s, quantity, /*quick=*/true, dir,
                                      [&](const std::string& n) { notes.push_back(n); });
}

TEST(WorkPrecision, EachPointIsTheFigureCompareGivesAtItsSetting) {
  TemporaryDirectory work("impactbench_wp");
  std::vector<std::string> notes;
  const auto points = sweep_points("bouncing_ball", 0, "apex_error", work.path(), notes);
  // Every engine the ball lists that this build has, at the quick suite's three values.
  const auto s = scenario::load_scenario_by_name("bouncing_ball");
  std::size_t engines = 0;
  for (const auto& info : adapters::engine_registry())
    if (info.run && s.supports_engine(info.name)) ++engines;
  ASSERT_EQ(points.size(), 3 * engines);
  EXPECT_TRUE(notes.empty()) << notes.front();
  // compare's flags for the same run: the step, or the integrator's two tolerances.
  for (const auto& [engine, setting] : std::vector<std::pair<std::string, std::string>>{
           {"moreau", "dt"}, {"event", "tol"}, {"box2d", "dt"}}) {
    const double value = compare::work_precision_values(setting, true).front();
    const auto point = std::find_if(points.begin(), points.end(), [&](const auto& p) {
      return p.engine == engine && p.value == value;
    });
    ASSERT_NE(point, points.end()) << engine;
    EXPECT_EQ(point->setting, setting);
    const std::string v = output::number_text(value);
    const std::string flags =
        setting == "dt" ? "--dt " + v : "--option event.rtol=" + v + " --option event.atol=" + v;
    TemporaryDirectory capture("impactbench_wp_cmp");
    const auto compared = run_program(IMPACTBENCH_CLI,
                                      "compare bouncing_ball --engines " + engine + " " + flags +
                                          " --out '" + capture.path().string() + "'",
                                      capture.path());
    ASSERT_EQ(compared.exit_code, 0) << compared.err;
    const auto metrics = read_csv_table(capture.path() / "metrics.csv");
    ASSERT_EQ(metrics.rows.size(), 1u) << engine;
    EXPECT_EQ(output::number_text(point->error),
              output::number_text(std::abs(std::stod(metrics.at(0, "apex_error")))))
        << engine;
  }
  // The folder is a sweep of its own: run again by hand, every point is already done.
  TemporaryDirectory capture("impactbench_wp_again");
  const fs::path dt_dir = work.path() / "dt";
  const auto again =
      run_program(IMPACTBENCH_CLI,
                  "sweep '" + (dt_dir / "spec.toml").string() + "' --out '" + dt_dir.string() + "'",
                  capture.path());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("sweep: 0 points ran (0 failed or timed out), " +
                           std::to_string(3 * (engines - 1)) + " already done"),
            std::string::npos)
      << again.out;
}

TEST(WorkPrecision, AFailedPointIsKeptWithItsReason) {
  TemporaryDirectory work("impactbench_wp_fail");
  std::vector<std::string> notes;
  const auto points = sweep_points("sliding_block", 0.02, "no_such_error", work.path(), notes);
  ASSERT_FALSE(points.empty());
  EXPECT_EQ(notes.size(), points.size());
  for (const auto& p : points) {
    EXPECT_TRUE(std::isnan(p.error)) << p.engine;
    EXPECT_NE(p.failure.find("no_such_error"), std::string::npos) << p.failure;
  }
  // summary.md lists every one of them as failed.
  const std::string md = compare::work_precision_markdown(points);
  std::size_t failed = 0;
  for (auto at = md.find("**failed:** no no_such_error"); at != std::string::npos;
       at = md.find("**failed:** no no_such_error", at + 1))
    ++failed;
  EXPECT_EQ(failed, points.size()) << md;
}

TEST(WorkPrecision, TheSummaryTableShowsMeasuredAndFailedPoints) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<compare::WorkPoint> points{{"moreau", "dt", 1e-3, 2.5e-4, 0.0125, ""},
                                               {"bullet", "dt", 4e-3, nan, nan, "run failed: a|b"}};
  const std::string md = compare::work_precision_markdown(points);
  EXPECT_NE(md.find("\n| moreau | dt | 0.001 | 0.00025 | 0.0125 |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("\n| bullet | dt | 0.004 | **failed:** run failed: a\\|b | – |\n"),
            std::string::npos)
      << md;
}

}  // namespace
}  // namespace impactbench
