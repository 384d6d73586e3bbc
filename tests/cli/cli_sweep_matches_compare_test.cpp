// `impactbench sweep` runs each point as `compare --engines ENGINE` runs it: every figure of
// the merged CSV but the timings equals, as text, the one of the equivalent compare command's
// metrics.csv, point by point; and the ids are stable (a reordered spec gives the same ids).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/csv_table.hpp"

namespace {

namespace fs = std::filesystem;
using impactbench::test_support::read_csv_table;
using impactbench::test_support::run_program;
using impactbench::test_support::TemporaryDirectory;

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// "restitution=0.5; theta=1" → " --set restitution=0.5" (or --option ENGINE.theta=1).
std::string flags(const std::string& joined, const std::string& flag, const std::string& prefix) {
  std::string out;
  std::size_t start = 0;
  while (start < joined.size()) {
    const std::size_t end = std::min(joined.find("; ", start), joined.size());
    out += " " + flag + " " + prefix + joined.substr(start, end - start);
    start = end + 2;
  }
  return out;
}

// Writes `text` as work/name, sweeps it with --merge into work/name.out and reads the merged CSV.
impactbench::test_support::CsvTable merged_sweep(const TemporaryDirectory& work,
                                                 const TemporaryDirectory& capture,
                                                 const std::string& name, const std::string& text) {
  std::ofstream(work.path() / name) << text;
  const fs::path dir = work.path() / (name + ".out");
  const auto outcome = run_program(
      IMPACTBENCH_CLI,
      "sweep '" + (work.path() / name).string() + "' --out '" + dir.string() + "' --merge",
      capture.path());
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  return read_csv_table(dir / "sweep.csv");
}

TEST(SweepMatchesCompare, EveryPointsFiguresEqualTheEquivalentCompare) {
  TemporaryDirectory work("impactbench_sweep_cmp");
  TemporaryDirectory capture("impactbench_capture");
  const fs::path spec = work.path() / "spec.toml";
  std::ofstream(spec) << "scenarios = [\"bouncing_ball\"]\n"
                         "engines = [\"moreau\", \"event\"]\n"
                         "duration = 0.6\n"
                         "[grid]\n"
                         "dt = [1e-3, 2e-3]\n"
                         "[grid.set]\n"
                         "restitution = [0.5, 0.8]\n"
                         "[grid.option]\n"
                         "\"moreau.theta\" = [0.5, 1]\n";
  const fs::path dir = work.path() / "out";
  const auto sweep =
      run_program(IMPACTBENCH_CLI,
                  "sweep '" + spec.string() + "' --out '" + dir.string() + "' --jobs 2 --merge",
                  capture.path());
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  const auto merged = read_csv_table(dir / "sweep.csv");
  // moreau: 2 dt x 2 restitution x 2 theta; event: no step, no theta: 2 restitution.
  ASSERT_EQ(merged.rows.size(), 10u);
  std::size_t compared = 0;
  for (std::size_t i = 0; i < merged.rows.size(); ++i) {
    const std::string engine = merged.at(i, "engine");
    EXPECT_EQ(merged.at(i, "status"), "ok") << merged.at(i, "reason");
    std::string args = "compare bouncing_ball --engines " + engine + " --duration 0.6 --no-plots";
    if (!merged.at(i, "dt").empty()) args += " --dt " + merged.at(i, "dt");
    args += flags(merged.at(i, "sets"), "--set", "");
    args += flags(merged.at(i, "options"), "--option", engine + ".");
    const fs::path cmp = work.path() / ("cmp" + std::to_string(i));
    const auto outcome =
        run_program(IMPACTBENCH_CLI, args + " --out '" + cmp.string() + "'", capture.path());
    ASSERT_EQ(outcome.exit_code, 0) << args << "\n" << outcome.err;
    const auto metrics = read_csv_table(cmp / "metrics.csv");
    ASSERT_EQ(metrics.rows.size(), 1u) << args;
    EXPECT_EQ(merged.at(i, "settings"), metrics.at(0, "settings")) << args;
    std::size_t figures = 0;
    for (const std::string& name : metrics.columns) {
      if (name == "engine" || name == "settings" || ends_with(name, "_seconds")) continue;
      if (merged.column(name) < 0) continue;  // text columns of compare only (note, failure)
      EXPECT_EQ(merged.at(i, name), metrics.at(0, name)) << args << ": " << name;
      ++figures;
    }
    EXPECT_GE(figures, 15u) << args;
    // The CPU time of stepping is measured, not copied: positive and below a second.
    const double cpu = std::stod(merged.at(i, "cpu_seconds"));
    EXPECT_GT(cpu, 0.0);
    EXPECT_LT(cpu, 1.0);
    ++compared;
  }
  EXPECT_EQ(compared, 10u);
  // The restitution changes the figures (the ball hits the ground at t = 0.43 s).
  EXPECT_NE(merged.at(0, "linf_error"), "");
  std::set<std::string> distinct_energy;
  for (std::size_t i = 0; i < merged.rows.size(); ++i)
    distinct_energy.insert(merged.at(i, "energy_drift"));
  EXPECT_GE(distinct_energy.size(), 4u);
}

// grid.settings runs a point as `compare --settings SET` runs it, for the engines that have the
// set (Bullet: 20 solver iterations at its expert set, 50 at its defaults); an engine without one
// (Moreau–Jean) gets one point, at its defaults; and the `default` point is the point of no
// settings axis.
TEST(SweepMatchesCompare, TheSettingsAxisRunsEachSetAsCompareDoes) {
  TemporaryDirectory work("impactbench_sweep_sets");
  TemporaryDirectory capture("impactbench_capture");
  const auto sweep = [&](const std::string& name, const std::string& grid) {
    return merged_sweep(work, capture, name,
                        "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\", \"bullet\"]\n"
                        "duration = 0.6\n" +
                            grid);
  };
  const auto merged = sweep("sets.toml", "[grid]\nsettings = [\"default\", \"expert\"]\n");
  ASSERT_EQ(merged.rows.size(), 3u);
  std::set<std::string> rows;
  for (std::size_t i = 0; i < merged.rows.size(); ++i) {
    const std::string engine = merged.at(i, "engine"), set = merged.at(i, "settings_set");
    rows.insert(engine + " " + set);
    EXPECT_EQ(merged.at(i, "status"), "ok") << merged.at(i, "reason");
    const fs::path cmp = work.path() / ("cmp" + std::to_string(i));
    const std::string args = "compare bouncing_ball --engines " + engine + " --settings " + set +
                             " --duration 0.6 --no-plots --out '" + cmp.string() + "'";
    const auto outcome = run_program(IMPACTBENCH_CLI, args, capture.path());
    ASSERT_EQ(outcome.exit_code, 0) << args << "\n" << outcome.err;
    const auto metrics = read_csv_table(cmp / "metrics.csv");
    ASSERT_EQ(metrics.rows.size(), 1u) << args;
    // The sweep lists the settings it asks for; compare also those the engine builds in.
    EXPECT_EQ(metrics.at(0, "settings").rfind(merged.at(i, "settings"), 0), 0u) << args;
    for (const char* name : {"linf_error", "energy_drift", "steps", "max_penetration"})
      EXPECT_EQ(merged.at(i, name), metrics.at(0, name)) << args << ": " << name;
  }
  EXPECT_EQ(rows, (std::set<std::string>{"moreau default", "bullet default", "bullet expert"}));
  // The set is in force: Bullet's 20 solver iterations at its expert set, 50 at its defaults.
  for (std::size_t i = 0; i < merged.rows.size(); ++i)
    if (merged.at(i, "engine") == "bullet") {
      EXPECT_NE(
          merged.at(i, "settings")
              .find(merged.at(i, "settings_set") == "expert" ? "solver_iterations=20 (expert)"
                                                             : "solver_iterations=50 (default)"),
          std::string::npos)
          << merged.at(i, "settings");
    }
  // Without the axis, the same default points, with the same ids.
  const auto plain = sweep("plain.toml", "");
  std::set<std::string> default_ids, plain_ids;
  for (std::size_t i = 0; i < merged.rows.size(); ++i)
    if (merged.at(i, "settings_set") == "default") default_ids.insert(merged.at(i, "id"));
  for (std::size_t i = 0; i < plain.rows.size(); ++i) plain_ids.insert(plain.at(i, "id"));
  EXPECT_EQ(default_ids, plain_ids);
}

TEST(SweepMatchesCompare, IdsAreStableWhenTheSpecIsReordered) {
  TemporaryDirectory work("impactbench_sweep_ids");
  TemporaryDirectory capture("impactbench_capture");
  const auto ids = [&](const std::string& name, const std::string& text) {
    const auto table = merged_sweep(work, capture, name, text);
    std::set<std::string> out;
    for (std::size_t i = 0; i < table.rows.size(); ++i)
      out.insert(table.at(i, "id") + " " + table.at(i, "dt") + " " + table.at(i, "sets"));
    return out;
  };
  const auto first = ids("a.toml",
                         "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\nduration = 0.1\n"
                         "[grid]\ndt = [1e-3, 2e-3]\n[grid.set]\nrestitution = [0.5, 0.8]\n");
  const auto second =
      ids("b.toml",
          "duration = 0.1\nengines = [\"moreau\"]\nscenarios = [\"bouncing_ball\"]\n"
          "[grid.set]\nrestitution = [0.8, 0.5]\n[grid]\ndt = [2e-3, 1e-3]\n");
  EXPECT_EQ(first.size(), 4u);
  EXPECT_EQ(first, second);
}

}  // namespace
