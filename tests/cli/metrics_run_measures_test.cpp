// What a run reports about itself: process CPU time split between the engine's stepping and
// our recording, the deepest penetration measured on the model's geometry, impact events that
// mean impacts, and work-precision points that fail without disappearing.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/contact_events.hpp"
#include "lib/engines/run_timer.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/metrics/penetration.hpp"
#include "tools/compare/asked_settings.hpp"
#include "tools/compare/compare.hpp"
#include "tools/engines/box2d/box2d_engine.hpp"
#include "tools/engines/bullet/bullet_engine.hpp"
#include "tools/engines/fixed_step/scene_from_scenario.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

using engines::ClosedContact;
using engines::ContactEvents;
using engines::ImpactCriteria;
using engines::RunTimer;
using output::EventRecord;

// Spends `seconds` of this process's CPU time.
void burn_cpu(double seconds) {
  const double until = engines::process_cpu_seconds() + seconds;
  volatile double sink = 0.0;
  while (engines::process_cpu_seconds() < until) sink = sink + 1.0;
}

// dt: none for the event-driven engine, which has no step.
engines::RunResult run_named(const std::string& engine, const scenario::Scenario& s,
                             std::optional<double> dt, double duration,
                             std::vector<std::pair<std::string, std::string>> settings = {}) {
  engines::SettingsRequest request;
  request.dt = dt;
  request.duration = duration;
  request.options = std::move(settings);
  return adapters::run_engine(engine, s, engines::resolve_run_options(engine, s, request));
}

std::vector<double> impact_times(const engines::RunResult& run) {
  std::vector<double> times;
  for (const EventRecord& e : run.events)
    if (e.kind == "impact") times.push_back(e.t);
  return times;
}

// ---- the clock ---------------------------------------------------------------------------

TEST(RunTimer, SleepingCostsWallTimeButNoProcessCpuTime) {
  RunTimer timer;
  timer.start(RunTimer::Phase::kRecord);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  timer.stop();
  EXPECT_GE(timer.wall_seconds(), 0.2);
  // A wall clock (the old steady_clock timing) would report 0.2 s here.
  EXPECT_LT(timer.record_cpu_seconds(), 0.02);
  EXPECT_EQ(timer.engine_cpu_seconds(), 0.0);
}

TEST(RunTimer, EachPhaseIsChargedWithTheCpuTimeSpentInIt) {
  RunTimer timer;
  timer.start(RunTimer::Phase::kEngine);
  burn_cpu(0.06);
  {
    const auto recording = timer.scoped(RunTimer::Phase::kRecord);
    burn_cpu(0.02);
  }
  burn_cpu(0.03);  // back in the engine phase after the scope
  timer.stop();
  EXPECT_GE(timer.engine_cpu_seconds(), 0.09);
  EXPECT_LT(timer.engine_cpu_seconds(), 0.09 + 0.01);
  EXPECT_GE(timer.record_cpu_seconds(), 0.02);
  EXPECT_LT(timer.record_cpu_seconds(), 0.02 + 0.01);
}

// The reference engines' step must not be charged with the adapter's work: the energy column is
// computed while recording, so a deliberately slow energy function must land in
// record_cpu_seconds and leave engine_cpu_seconds at the cost of stepping one ball.
class ReferenceEngineTiming : public testing::TestWithParam<std::string> {};

TEST_P(ReferenceEngineTiming, TheAdaptersRecordingIsNotChargedToTheEngine) {
  const auto s = scenario::load_scenario_by_name("bouncing_ball");
  // 100 steps of 1 ms, 101 recorded states
  adapters::ReferenceScene scene = adapters::make_reference_scene(s, 0.1, 1e-3);
  const auto energy = scene.energy;
  constexpr double kEnergyCost = 5e-4;  // [s] of CPU per recorded state
  scene.energy = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    burn_cpu(kEnergyCost);
    return energy(q, v);
  };
  const engines::RunResult run =
      GetParam() == "box2d" ? adapters::run_box2d(scene) : adapters::run_bullet(scene);
  const double injected = 101 * kEnergyCost;
  EXPECT_GE(run.record_cpu_seconds, injected);
  EXPECT_LT(run.engine_cpu_seconds, injected / 5) << "the recording was timed as stepping";
  EXPECT_GE(run.wall_seconds, injected);
  EXPECT_EQ(run.step_count, 100);
  EXPECT_FALSE(run.unconverged_steps.has_value()) << "fixed iterations: no tolerance";
  EXPECT_FALSE(run.unconverged_note.empty());
}

INSTANTIATE_TEST_SUITE_P(BothEngines, ReferenceEngineTiming, testing::Values("box2d", "bullet"));

TEST(RunFigures, OurEnginesCountTheirStepsAndUnconvergedSolves) {
  const auto s = scenario::load_scenario_by_name("disk_pile", {{"count", 20}});
  // Two sweeps do not reach the tolerance on a pile: steps with contacts stay unconverged.
  const auto run =
      run_named("moreau", s, 1e-3, 0.2, {{"on_failure", "warn"}, {"max_iterations", "2"}});
  ASSERT_EQ(run.steps.size(), 200u);
  EXPECT_EQ(run.step_count, 200);
  long unconverged = 0, contacts = 0;
  for (const auto& step : run.steps) {
    unconverged += step.converged ? 0 : 1;
    contacts += step.active_contacts;
  }
  ASSERT_TRUE(run.unconverged_steps.has_value());
  EXPECT_GT(unconverged, 0);
  EXPECT_EQ(*run.unconverged_steps, unconverged);
  EXPECT_DOUBLE_EQ(run.mean_contacts, contacts / 200.0);
  EXPECT_GT(run.engine_cpu_seconds, 0.0);
  EXPECT_GT(run.record_cpu_seconds, 0.0);
}

// ---- max_penetration ---------------------------------------------------------------------

// At coarse steps the stepper takes the first impact late and the ball sinks into the ground.
// The reported depth must be the trajectory's own: radius − lowest height of the centre.
TEST(MaxPenetration, IsTheDepthOfTheTrajectoryEvenWhenAnImpactIsTakenLate) {
  const auto s = scenario::load_scenario_by_name("bouncing_ball");
  const double radius = s.bodies.front().radius;
  for (const double dt : {5e-3, 1e-2}) {
    const auto run = run_named("moreau", s, dt, 1.0);
    const auto& names = run.trajectory.position_names;
    const auto y = std::find(names.begin(), names.end(), "ball.y") - names.begin();
    ASSERT_LT(y, static_cast<long>(names.size()));
    double lowest = std::numeric_limits<double>::infinity();
    for (const auto& sample : run.trajectory.samples) lowest = std::min(lowest, sample.q[y]);
    const double depth = std::max(0.0, radius - lowest);
    EXPECT_NEAR(run.max_penetration, depth, 1e-12) << "dt = " << dt;
    double reported = std::nan("");
    for (const auto& [name, value] : compare::run_metrics(s, run, nullptr))
      if (name == "max_penetration") reported = value;
    EXPECT_EQ(reported, run.max_penetration) << "metrics.csv reports another figure";
  }
}

// Moreau–Jean reports its own deepest penetration (every candidate within the contact margin at
// the start of every step, and the final state). The tracker the other engines use, searching
// every state of the run on the model's geometry, must find the same depth to the bit.
TEST(MaxPenetration, MoreauJeansOwnDepthIsTheTrackersOverEveryState) {
  for (const char* scene : {"disk_pile", "sphere_pile"}) {
    const auto s = scenario::load_scenario_by_name(scene, {{"count", 40}});
    const auto run = run_named("moreau", s, 2e-3, 0.4);
    ASSERT_EQ(run.trajectory.samples.size(), static_cast<std::size_t>(run.step_count) + 1)
        << scene << ": every state kept";
    const engines::BuiltSystem built = engines::build_system(s);
    metrics::PenetrationTracker tracker(*built.system);
    for (const auto& sample : run.trajectory.samples) tracker.add(sample.q, sample.v);
    EXPECT_GT(tracker.deepest(), 0.0) << scene << ": the pile's contacts penetrate";
    EXPECT_EQ(run.max_penetration, tracker.deepest()) << scene;
  }
}

// ---- events ------------------------------------------------------------------------------

TEST(ContactEvents, AFastClosingIsAnImpactAndAShortSlowReclosureIsNot) {
  ContactEvents derive(ImpactCriteria{0.02, 2e-3});
  std::vector<EventRecord> events;
  derive.after_step(0.1, {{"c", 3.0, 1.5, 0.25}}, events);    // lands at 3 m/s
  derive.after_step(0.2, {}, events);                         // lifts off
  derive.after_step(0.201, {{"c", 0.01, 0.1, 0.0}}, events);  // back after 1 ms at 1 cm/s
  derive.after_step(0.202, {}, events);                       // lifts off again
  derive.after_step(0.205, {{"c", 0.01, 0.1, 0.0}}, events);  // 3 ms open: a landing
  derive.after_step(0.206, {}, events);
  derive.after_step(0.2065, {{"c", 0.5, 0.1, 0.0}}, events);  // 0.5 ms open but fast
  const std::vector<std::string> kinds{"impact", "liftoff", "closure", "liftoff",
                                       "impact", "liftoff", "impact"};
  ASSERT_EQ(events.size(), kinds.size());
  for (std::size_t i = 0; i < kinds.size(); ++i) EXPECT_EQ(events[i].kind, kinds[i]) << i;
  EXPECT_EQ(events[0].impulse_n, 1.5);
  EXPECT_EQ(events[0].impulse_t, 0.25);
  EXPECT_EQ(events[1].t, 0.2);
  EXPECT_EQ(events[2].from_mode, "open");
  EXPECT_EQ(events[2].to_mode, "closed");
}

TEST(ContactEvents, BothThresholdsAreStrict) {
  ContactEvents derive(ImpactCriteria{0.02, 2e-3});
  std::vector<EventRecord> events;
  derive.after_step(0.001, {{"a", 0.02, 1.0, 0.0}}, events);  // at the speed, 1 ms from start
  derive.after_step(0.002, {}, events);
  derive.after_step(0.004, {{"a", 0.0, 1.0, 0.0}}, events);  // open exactly 2 ms
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].kind, "closure");
  EXPECT_EQ(events[2].kind, "closure");
}

TEST(ContactEvents, CriteriaAreSettingsOfEveryTimeStepper) {
  const auto ball = scenario::load_scenario_by_name("bouncing_ball");
  for (const std::string engine : {"moreau", "box2d", "bullet"}) {
    engines::SettingsRequest request;
    request.options = {{"impact_velocity", "0.5"}, {"impact_open_time", "0.01"}};
    const auto options = engines::resolve_run_options(engine, ball, request);
    EXPECT_EQ(engines::setting_value(options.settings, "impact_velocity"), "0.5") << engine;
    EXPECT_EQ(engines::setting_value(options.settings, "impact_open_time"), "0.01") << engine;
    try {
      run_named(engine, ball, 1e-3, 0.01, {{"impact_velocity", "-1"}});
      ADD_FAILURE() << engine << " accepted a negative impact_velocity";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(engine + ": setting 'impact_velocity'"),
                std::string::npos)
          << e.what();
    }
    EXPECT_THROW(run_named(engine, ball, 1e-3, 0.01, {{"impact_open_time", "soon"}}),
                 std::invalid_argument);
  }
}

// A slender block rocks on alternate corners; each landing is one impact. Moreau–Jean opens
// the loaded pivot corner for a step now and then; those re-closures must not count as
// impacts. The oracle is the event-driven engine, which locates every impact.
TEST(ContactEvents, MoreauJeanCountsTheRockingBlocksImpactsLikeTheEventDrivenEngine) {
  const auto s = scenario::load_scenario_by_name(
      "rocking_block", {{"width", 0.3}, {"height", 1.2}, {"tilt", 2.8647889756541161}});
  // Both engines' 14th impact lies before 2.95 s and their 15th after it (Moreau–Jean's
  // trajectory runs ahead by under 0.02 s at its end).
  const double duration = 2.95;
  const auto reference = impact_times(run_named("event", s, std::nullopt, duration));
  const auto moreau_run = run_named("moreau", s, s.dt, duration);
  const auto moreau = impact_times(moreau_run);
  ASSERT_GE(reference.size(), 2u);
  ASSERT_EQ(moreau.size(), reference.size());
  // One to one: each impact is closer to its partner than half the shortest interval between
  // the reference's impacts (so no impact can stand in for its neighbour).
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < reference.size(); ++i)
    shortest = std::min(shortest, reference[i] - reference[i - 1]);
  for (std::size_t i = 0; i < reference.size(); ++i)
    EXPECT_LT(std::abs(moreau[i] - reference[i]), shortest / 2) << "impact " << i;
  // The re-closures are there, counted as their own kind.
  const auto closures = std::count_if(moreau_run.events.begin(), moreau_run.events.end(),
                                      [](const EventRecord& e) { return e.kind == "closure"; });
  EXPECT_GT(closures, 0);
}

// What each engine was asked to do, as the suite's per-scenario tables show it: the values in
// force of the step, tolerance, solver and iteration keys, given ones and defaults alike, and
// none of the other keys.
TEST(AskedSettings, NameTheStepToleranceSolverAndIterationsInForce) {
  const auto ball = scenario::load_scenario_by_name("bouncing_ball");
  engines::SettingsRequest request;
  request.dt = 2.5e-4;
  request.options = {{"max_iterations", "77"}};
  EXPECT_EQ(compare::asked_settings_text(engines::resolve_run_options("moreau", ball, request)),
            "dt=0.00025 solver=nsgs tolerance=" +
                engines::setting_value(engines::resolve_run_options("moreau", ball).settings,
                                       "tolerance") +
                " max_iterations=77");
  engines::SettingsRequest box2d_request;
  box2d_request.options = {{"velocity_iterations", "12"}};
  const auto box2d = engines::resolve_run_options("box2d", ball, box2d_request);
  EXPECT_EQ(compare::asked_settings_text(box2d),
            "dt=" + engines::setting_value(box2d.settings, "dt") +
                " velocity_iterations=12 position_iterations=" +
                engines::setting_value(box2d.settings, "position_iterations"));
  const std::string mujoco =
      compare::asked_settings_text(engines::resolve_run_options("mujoco", ball));
  for (const char* key :
       {"timestep=", "solver=", "iterations=", "tolerance=", "cone=", "noslip_iterations="})
    EXPECT_NE(mujoco.find(key), std::string::npos) << key << " in " << mujoco;
  EXPECT_EQ(mujoco.find("solref"), std::string::npos) << mujoco;
}

}  // namespace
}  // namespace impactbench
