// A run's trajectory as `impactbench run` writes it: streamed sample by sample into the CSV
// (nothing kept in memory), sampled on a grid of simulated time, and read back bit for bit equal
// to the states the engine recorded in memory.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/output/run_outputs.hpp"
#include "lib/scenario/scenario.hpp"
#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/lib/double_bits.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

namespace fs = std::filesystem;
using engines::RunResult;

class StreamedRun : public ::testing::Test {
 protected:
  /// `engine` on `scenario` (its defaults, `duration` when > 0) with `recording`.
  static RunResult run(const std::string& engine, const std::string& scenario,
                       engines::RecordingOptions recording, double duration = 0.0,
                       const scenario::ParameterOverrides& overrides = {}) {
    const auto s = scenario::load_scenario_by_name(
        scenario, overrides, duration > 0.0 ? std::optional<double>(duration) : std::nullopt);
    engines::RunOptions options = engines::resolve_run_options(engine, s);
    options.recording = std::move(recording);
    return adapters::run_engine(engine, s, options);
  }

  test_support::TemporaryDirectory work_{"impactbench_stream"};
  const fs::path directory_ = work_.path();
};

/// The CSV's rows, each cell read with strtod (the header line is returned apart).
std::vector<std::vector<double>> read_rows(const fs::path& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) {
      char* end = nullptr;
      row.push_back(std::strtod(cell.c_str(), &end));
      EXPECT_EQ(*end, '\0') << "cell '" << cell << "' is not a number";
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

/// The numbers of a sample in the CSV's column order.
std::vector<double> row_of(const output::TrajectorySample& sample) {
  std::vector<double> row{sample.t};
  row.insert(row.end(), sample.q.begin(), sample.q.end());
  row.insert(row.end(), sample.v.begin(), sample.v.end());
  row.push_back(sample.energy);
  return row;
}

using test_support::bits;

/// Writes every kept sample through RunOutputs as `impactbench run` does, and keeps it too.
engines::RecordingOptions streaming_into(output::RunOutputs& outputs, bool keep) {
  engines::RecordingOptions recording;
  recording.keep_samples = keep;
  recording.keep_steps = keep;
  recording.sample_sink = [&outputs](const output::Trajectory& names,
                                     const output::TrajectorySample& sample) {
    outputs.write_sample(names, sample);
  };
  return recording;
}

TEST_F(StreamedRun, TrajectoryReadBackEqualsTheRecordedOneBitForBit) {
  // Moreau–Jean on a small pile (many contacts, every digit of the state in use) and the event
  // engine on the bouncing ball (event instants in the time column).
  struct Case {
    std::string engine, scenario;
    scenario::ParameterOverrides overrides;
    double duration = 0.0;  // [s]: the pile settles (contacts in every row) by 0.6 s
  };
  for (const auto& [engine, scenario, overrides, duration] : std::vector<Case>{
           {"moreau", "disk_pile", {{"count", 20}}, 0.6}, {"event", "bouncing_ball", {}, 2.0}}) {
    const fs::path path = directory_ / (engine + ".csv");
    output::RunOutputs outputs(path, std::nullopt);
    const RunResult result =
        run(engine, scenario, streaming_into(outputs, /*keep=*/true), duration, overrides);
    outputs.commit(result.events);
    std::string header;
    const auto rows = read_rows(path, header);
    ASSERT_EQ(rows.size(), result.trajectory.samples.size()) << engine;
    ASSERT_GT(rows.size(), 100u) << engine;
    long cells = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const std::vector<double> expected = row_of(result.trajectory.samples[i]);
      ASSERT_EQ(rows[i].size(), expected.size()) << engine << " row " << i;
      for (std::size_t j = 0; j < expected.size(); ++j, ++cells)
        ASSERT_EQ(bits(rows[i][j]), bits(expected[j]))
            << engine << " row " << i << " column " << j << ": " << rows[i][j] << " read, "
            << expected[j] << " recorded";
    }
    EXPECT_EQ(static_cast<std::size_t>(cells),
              rows.size() * (1 + result.trajectory.position_names.size() +
                             result.trajectory.velocity_names.size() + 1));
  }
}

TEST_F(StreamedRun, AStreamedRunKeepsNothingInMemoryAndReportsTheSameFigures) {
  const RunResult kept = run("moreau", "disk_pile", {}, 0.6, {{"count", 20}});
  const fs::path path = directory_ / "streamed.csv";
  output::RunOutputs outputs(path, std::nullopt);
  const RunResult streamed =
      run("moreau", "disk_pile", streaming_into(outputs, /*keep=*/false), 0.6, {{"count", 20}});
  outputs.commit(streamed.events);
  EXPECT_TRUE(streamed.trajectory.samples.empty());
  EXPECT_TRUE(streamed.steps.empty());
  // 600 steps of 1 ms: the initial state and one row per step.
  EXPECT_EQ(streamed.sample_count, 601);
  EXPECT_EQ(kept.trajectory.samples.size(), 601u);
  std::string header;
  EXPECT_EQ(read_rows(path, header).size(), 601u);
  // The figures come from running totals, equal to those of the records kept in memory.
  EXPECT_EQ(streamed.step_count, 600);
  EXPECT_EQ(kept.steps.size(), 600u);
  EXPECT_EQ(streamed.step_count, kept.step_count);
  EXPECT_EQ(streamed.unconverged_steps, kept.unconverged_steps);
  EXPECT_EQ(streamed.mean_contacts, kept.mean_contacts);
  EXPECT_EQ(streamed.max_penetration, kept.max_penetration);
  EXPECT_EQ(streamed.worst_unconverged_residual, kept.worst_unconverged_residual);
  EXPECT_EQ(streamed.first_energy, kept.trajectory.samples.front().energy);
  EXPECT_EQ(streamed.last_energy, kept.trajectory.samples.back().energy);
  ASSERT_EQ(streamed.events.size(), kept.events.size());
  EXPECT_GT(kept.mean_contacts, 1.0);  // the pile has settled: the totals count something
}

TEST_F(StreamedRun, SamplingKeepsTheFirstStateOnePerIntervalAndTheLast) {
  // Box2D: a fixed step of 1 ms, so the kept times are known in advance.
  const RunResult every = run("box2d", "bouncing_ball", {}, 0.1);
  engines::RecordingOptions sampled_recording;
  sampled_recording.sample_interval = 0.0075;  // 7.5 steps: the grid falls between steps
  const RunResult sampled = run("box2d", "bouncing_ball", sampled_recording, 0.1);
  ASSERT_EQ(every.trajectory.samples.size(), 101u);
  // Kept: t = 0, the first step end at or after each k · 7.5 ms (8, 15, 23, 30, ..., 98 ms),
  // then the last state (100 ms): 1 + 13 + 1.
  std::vector<double> expected_times{0.0};
  for (int k = 1; 0.0075 * k <= 0.1; ++k) expected_times.push_back(std::ceil(7.5 * k - 1e-9) / 1e3);
  if (expected_times.back() < 0.1) expected_times.push_back(0.1);
  ASSERT_EQ(sampled.trajectory.samples.size(), expected_times.size());
  ASSERT_EQ(expected_times.size(), 15u);
  std::size_t at = 0;
  for (std::size_t i = 0; i < expected_times.size(); ++i) {
    const auto& sample = sampled.trajectory.samples[i];
    EXPECT_NEAR(sample.t, expected_times[i], 1e-12) << i;
    // The same state as the run that keeps every step: sampling only selects.
    while (at < every.trajectory.samples.size() && every.trajectory.samples[at].t < sample.t) ++at;
    ASSERT_LT(at, every.trajectory.samples.size());
    EXPECT_EQ(row_of(sample), row_of(every.trajectory.samples[at])) << i;
  }
  EXPECT_EQ(sampled.step_count, every.step_count);
}

TEST_F(StreamedRun, TheDefaultBudgetBoundsTheNumbersWritten) {
  // 40 disks: 2 + 6 · 40 = 242 columns; a budget of 5,000 numbers allows floor(5000 / 242) =
  // 20 rows over the run, i.e. one per 0.3 s / 20 = 15 ms: 20 grid points plus the first.
  engines::RecordingOptions budget;
  budget.max_values = 5000;
  budget.duration = 0.3;
  const RunResult result = run("moreau", "disk_pile", budget, 0.3, {{"count", 40}});
  const std::size_t columns =
      2 + result.trajectory.position_names.size() + result.trajectory.velocity_names.size();
  ASSERT_EQ(columns, 242u);
  EXPECT_EQ(result.trajectory.samples.size(), 21u);
  EXPECT_LE(result.trajectory.samples.size() * columns, 5000u + 2 * columns);
  EXPECT_EQ(result.step_count, 300);
}

TEST_F(StreamedRun, ARunThatFailsAfterStreamingLeavesNoFile) {
  const fs::path path = directory_ / "t.csv";
  {
    output::RunOutputs outputs(path, directory_ / "e.csv");
    engines::RecordingOptions recording = streaming_into(outputs, /*keep=*/false);
    long rows = 0;
    // A sink that fails after some rows, as a state turning non-finite would.
    recording.sample_sink = [&outputs, &rows](const output::Trajectory& names,
                                              const output::TrajectorySample& sample) {
      outputs.write_sample(names, sample);
      if (++rows == 50) throw std::runtime_error("stopped");
    };
    EXPECT_THROW(run("moreau", "bouncing_ball", recording, 0.2), std::runtime_error);
    EXPECT_EQ(rows, 50);
  }
  EXPECT_TRUE(fs::is_empty(directory_)) << "a temporary file was left behind";
}

}  // namespace
}  // namespace impactbench
