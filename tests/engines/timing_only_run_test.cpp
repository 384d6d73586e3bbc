// Timing-only runs (RecordingOptions::timing_only), the bare loops of the equal-work timing:
// the engine takes the same steps as in a recorded run (our recording only reads its state), so
// the final state is the same to the bit, the step count is the duration over the step, and
// nothing is recorded between the first and the last state. An engine without one refuses.
#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "tools/engines/engine_names.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

struct TimingOnlyCase {
  std::string engine;
  std::string scenario;
  scenario::ParameterOverrides overrides;
  double duration;              // [s]
  std::string step_key = "dt";  // the engine's setting of its time step
};

void PrintTo(const TimingOnlyCase& c, std::ostream* out) {
  *out << c.engine << " on " << c.scenario << " for " << c.duration << " s";
}

std::string case_name(const ::testing::TestParamInfo<TimingOnlyCase>& info) {
  return info.param.engine + "_" + info.param.scenario;
}

engines::RunOptions options_for(const TimingOnlyCase& c, const scenario::Scenario& s) {
  engines::SettingsRequest request;
  request.duration = c.duration;
  return engines::resolve_run_options(c.engine, s, request);
}

class TimingOnlyRun : public ::testing::TestWithParam<TimingOnlyCase> {};

TEST_P(TimingOnlyRun, EndsInTheRecordedRunsStateAfterTheSameStepsWithNothingBetween) {
  const TimingOnlyCase& c = GetParam();
  const scenario::Scenario s = scenario::load_scenario_by_name(c.scenario, c.overrides);
  const engines::RunOptions recorded_options = options_for(c, s);
  const engines::RunResult recorded = adapters::run_engine(c.engine, s, recorded_options);

  engines::RunOptions bare_options = recorded_options;
  bare_options.recording.timing_only = true;
  const engines::RunResult bare = adapters::run_engine(c.engine, s, bare_options);

  const double dt = engines::setting_number(recorded_options.settings, c.step_key);
  EXPECT_EQ(bare.step_count, std::lround(c.duration / dt));
  EXPECT_EQ(bare.step_count, recorded.step_count);
  // The first and the last state only: no samples, step records or events between them.
  ASSERT_EQ(bare.trajectory.samples.size(), 2u);
  EXPECT_TRUE(bare.steps.empty());
  EXPECT_TRUE(bare.events.empty());
  EXPECT_FALSE(recorded.events.empty());  // the recorded run saw the contacts: they happened
  const auto& first = bare.trajectory.samples.front();
  const auto& last = bare.trajectory.samples.back();
  const auto& recorded_last = recorded.trajectory.samples.back();
  EXPECT_EQ(first.t, 0.0);
  EXPECT_EQ(last.t, recorded_last.t);
  EXPECT_EQ(last.q, recorded_last.q) << "bare:\n" << last.q << "\nrecorded:\n" << recorded_last.q;
  EXPECT_EQ(last.v, recorded_last.v);
  EXPECT_GT(bare.engine_cpu_seconds, 0.0);
}

// Each engine with a bare loop on a scene whose contacts open and close.
INSTANTIATE_TEST_SUITE_P(
    EveryEngineWithABareLoop, TimingOnlyRun,
    ::testing::Values(TimingOnlyCase{engine_name::kMoreau, "bouncing_ball", {}, 1.5},
                      TimingOnlyCase{engine_name::kMoreau, "disk_pile", {{"count", 20}}, 0.3},
                      TimingOnlyCase{engine_name::kBox2d, "bouncing_ball", {}, 1.5},
                      TimingOnlyCase{engine_name::kBox2d, "disk_pile", {{"count", 20}}, 0.3},
                      TimingOnlyCase{engine_name::kBullet, "bouncing_ball", {}, 1.5},
                      TimingOnlyCase{engine_name::kBullet, "disk_pile", {{"count", 20}}, 0.3},
                      TimingOnlyCase{engine_name::kOde, "bouncing_ball", {}, 1.5},
                      TimingOnlyCase{engine_name::kMujoco, "bouncing_ball", {}, 1.5, "timestep"},
                      TimingOnlyCase{
                          engine_name::kMujoco, "disk_pile", {{"count", 20}}, 0.3, "timestep"}),
    case_name);

TEST(TimingOnlyRun, AnEngineWithoutOneRefusesInOneLine) {
  const scenario::Scenario s = scenario::load_scenario_by_name("bouncing_ball", {});
  engines::RunOptions options = options_for({engine_name::kEvent, "bouncing_ball", {}, 1.0}, s);
  options.recording.timing_only = true;
  try {
    adapters::run_engine(engine_name::kEvent, s, options);
    FAIL() << "the event-driven engine ran a timing-only run";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()),
              std::string(engine_name::kEvent) +
                  ": no timing-only run (the fixed-step engines and Moreau-Jean have one)");
  }
}

}  // namespace
}  // namespace impactbench
