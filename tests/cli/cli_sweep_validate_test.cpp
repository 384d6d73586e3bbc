// A [validate] sweep runs each point as `impactbench validate --engines ENGINE --tosses T
// --set NAME=VALUE` runs it: the scored and failed counts and the mean, median and 90th
// percentile of every score in the merged CSV equal, as text, those of validate's summary.md;
// so a fit of contact parameters over grid.set goes through the sweep machinery.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/csv_table.hpp"

namespace {

namespace fs = std::filesystem;
using impactbench::test_support::read_csv_table;
using impactbench::test_support::read_text;
using impactbench::test_support::run_program;
using impactbench::test_support::TemporaryDirectory;

// The cells of the row "| ENGINE | scored | failed | METRIC | unit | mean | median | p90 |".
std::vector<std::string> summary_row(const std::string& summary, const std::string& engine,
                                     const std::string& metric) {
  std::istringstream in(summary);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, '|');) {
      const auto first = cell.find_first_not_of(' ');
      const auto last = cell.find_last_not_of(' ');
      if (first != std::string::npos) cells.push_back(cell.substr(first, last - first + 1));
    }
    if (cells.size() == 8 && cells[0] == engine && cells[3] == metric) return cells;
  }
  return {};
}

// Writes `text` as a sweep file, sweeps it with --merge and reads the merged CSV.
impactbench::test_support::CsvTable swept(const TemporaryDirectory& work,
                                          const TemporaryDirectory& capture,
                                          const std::string& text) {
  const fs::path spec = work.path() / "fit.toml";
  std::ofstream(spec) << text;
  const fs::path dir = work.path() / "out";
  const auto sweep = run_program(
      IMPACTBENCH_CLI, "sweep '" + spec.string() + "' --out '" + dir.string() + "' --merge",
      capture.path());
  EXPECT_EQ(sweep.exit_code, 0) << sweep.err;
  return read_csv_table(dir / "sweep.csv");
}

// The summary.md of `validate ARGS` run into its own folder (the `n`th of a test).
std::string validate_summary(const TemporaryDirectory& work, const TemporaryDirectory& capture,
                             const std::string& args, std::size_t n) {
  const fs::path out = work.path() / ("validate" + std::to_string(n));
  const auto validate = run_program(
      IMPACTBENCH_CLI, "validate " + args + " --out '" + out.string() + "'", capture.path());
  EXPECT_EQ(validate.exit_code, 0) << args << "\n" << validate.err;
  return read_text(out / "summary.md");
}

TEST(SweepValidate, EveryPointEqualsTheValidateCommandOfItsParameters) {
  TemporaryDirectory work("impactbench_sweep_validate");
  TemporaryDirectory capture("impactbench_capture");
  const auto merged = swept(work, capture,
                            "scenarios = [\"cube_toss\"]\nengines = [\"moreau\", \"bullet\"]\n"
                            "[validate]\ntosses = \"1-9\"\n[grid.set]\nfriction = [0.2, 0.4]\n");
  ASSERT_EQ(merged.rows.size(), 4u);
  for (std::size_t i = 0; i < merged.rows.size(); ++i) {
    const std::string engine = merged.at(i, "engine"), sets = merged.at(i, "sets");
    EXPECT_EQ(merged.at(i, "status"), "ok") << merged.at(i, "reason");
    const std::string args = "--engines " + engine + " --tosses 1-9 --set " + sets;
    const std::string summary = validate_summary(work, capture, args, i);
    for (const char* metric : {"position", "rotation", "velocity", "first_contact_time"}) {
      const auto row = summary_row(summary, engine, metric);
      ASSERT_EQ(row.size(), 8u) << args << ": " << metric;
      EXPECT_EQ(merged.at(i, "scored"), row[1]) << args;
      EXPECT_EQ(merged.at(i, "failed"), row[2]) << args;
      EXPECT_EQ(merged.at(i, std::string(metric) + "_mean"), row[5]) << args << ": " << metric;
      EXPECT_EQ(merged.at(i, std::string(metric) + "_median"), row[6]) << args << ": " << metric;
      EXPECT_EQ(merged.at(i, std::string(metric) + "_p90"), row[7]) << args << ": " << metric;
    }
  }
  // The friction changes the scores (the cube slides on the board after landing).
  EXPECT_NE(merged.at(0, "position_mean"), merged.at(1, "position_mean"));
}

// An engine option axis reaches the validate runs of its engine's points: MuJoCo's solref time
// constant, swept, gives the figures of validate --option mujoco.solref_timeconst=VALUE.
TEST(SweepValidate, AnOptionAxisRunsAsValidateOption) {
  TemporaryDirectory work("impactbench_sweep_validate_option");
  TemporaryDirectory capture("impactbench_capture");
  const auto merged = swept(work, capture,
                            "scenarios = [\"cube_toss\"]\nengines = [\"mujoco\"]\n"
                            "[validate]\ntosses = \"1-5\"\n[grid.option]\n"
                            "\"mujoco.solref_timeconst\" = [0.005, 0.05]\n");
  ASSERT_EQ(merged.rows.size(), 2u);
  for (std::size_t i = 0; i < merged.rows.size(); ++i) {
    const std::string args =
        "--engines mujoco --tosses 1-5 --option mujoco." + merged.at(i, "options");
    const auto row = summary_row(validate_summary(work, capture, args, i), "mujoco", "position");
    ASSERT_EQ(row.size(), 8u) << args;
    EXPECT_EQ(merged.at(i, "position_mean"), row[5]) << args;
  }
  EXPECT_NE(merged.at(0, "position_mean"), merged.at(1, "position_mean"));
}

// The fits the docs report stay sweeps the program plans: merging an empty folder lists every
// point as missing: bench/cube_toss_fit.toml 125 (5 engines x 5 frictions x 5 restitutions),
// bench/cube_toss_fit_models.toml 54 (3 x 2 x (3 MuJoCo + 2 Bullet + 4 ODE settings)),
// bench/cube_toss_fit_solimp.toml 54 (3 x 2 x 3 dmin x 3 widths, MuJoCo alone).
TEST(SweepValidate, TheShippedFitsPlanTheirPoints) {
  TemporaryDirectory work("impactbench_sweep_fit");
  TemporaryDirectory capture("impactbench_capture");
  for (const auto& [file, points] :
       {std::pair<std::string, int>{"cube_toss_fit.toml", 125},
        std::pair<std::string, int>{"cube_toss_fit_models.toml", 54},
        std::pair<std::string, int>{"cube_toss_fit_solimp.toml", 54}}) {
    const fs::path spec = fs::path(IMPACTBENCH_TEST_DATA_DIR) / ".." / ".." / "bench" / file;
    const auto merge = run_program(
        IMPACTBENCH_CLI, "merge '" + spec.string() + "' --out '" + work.path().string() + "'",
        capture.path());
    EXPECT_EQ(merge.exit_code, 1) << merge.err;
    EXPECT_NE(merge.err.find("sweep: " + std::to_string(points) + " points have no result:"),
              std::string::npos)
        << file << ": " << merge.err;
  }
}

}  // namespace
