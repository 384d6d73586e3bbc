// The plank–box on every reference engine with joints (Box2D, Bullet, ODE, MuJoCo): the plank
// on a hinge to the world with its torsional spring and damper, the box free. Checked during
// the free phase before the box lands, where each part has a reference: the box falls freely
// (closed form) and the plank swings alone (our event-driven engine, an independent
// integrator run to 1e-10).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

double value_at(const engines::RunResult& run, const std::string& column, double t) {
  const auto& names = run.trajectory.position_names;
  const auto index = std::find(names.begin(), names.end(), column) - names.begin();
  EXPECT_LT(index, static_cast<long>(names.size())) << column;
  for (const auto& sample : run.trajectory.samples)
    if (std::abs(sample.t - t) < 1e-9) return sample.q[index];
  ADD_FAILURE() << "no sample at " << t;
  return std::nan("");
}

engines::RunResult run(const std::string& engine, const scenario::Scenario& s, double duration) {
  engines::SettingsRequest request;
  request.duration = duration;
  return adapters::run_engine(engine, s, engines::resolve_run_options(engine, s, request));
}

class PlankBoxOnEngine : public testing::TestWithParam<std::string> {};

TEST_P(PlankBoxOnEngine, FreePhaseFollowsTheFallAndTheSwingingPlank) {
  const auto s = scenario::load_scenario_by_name("plank_box");
  const double g = s.parameter("g"), dt = s.dt;
  // 0.1 s: before the box (0.1 m above the plank) can land, at fall_time = 0.143 s.
  const double t = 0.1;
  ASSERT_LT(t, s.analytic("fall_time"));
  const auto engine_run = run(GetParam(), s, t);
  const auto reference = run("event", s, t);
  // Derived: semi-implicit Euler in free fall, y_k = y0 − g dt² k(k + 1)/2, lags the exact fall
  // by g·dt·t/2. Box2D's float positions add 1e-6 m.
  const double y0 = s.find_body("box")->position.y();
  EXPECT_NEAR(value_at(engine_run, "box.y", t), y0 - g * t * t / 2 - g * dt * t / 2, 1e-6);
  // The plank swings from rest at 0 about φ_eq, so |φ̇| ≤ ω |φ_eq| (ω = plank_frequency,
  // damping only slows it). Semi-implicit Euler's positions trail the flow by about half a
  // step, dt·|φ̇|/2 (measured 4.1e-4 rad for every engine); the bound allows twice that for
  // the torque sampled at each step's start.
  const double omega = s.analytic("plank_frequency");
  const double swing_rate = omega * std::abs(s.analytic("plank_equilibrium"));
  EXPECT_NEAR(value_at(engine_run, "plank.phi", t), value_at(reference, "plank.phi", t),
              dt * swing_rate);
}

TEST_P(PlankBoxOnEngine, BoxLandsAndStaysOnThePlank) {
  // Over the whole run the box neither sinks into nor leaves the plank: every engine's deepest
  // penetration stays below the plank's half thickness and the box ends above the hinge.
  const auto s = scenario::load_scenario_by_name("plank_box");
  const auto r = run(GetParam(), s, s.duration);
  EXPECT_LT(r.max_penetration, s.parameter("l_P") / 2);
  EXPECT_GT(value_at(r, "box.y", s.duration), 0.0);
  EXPECT_FALSE(r.events.empty());  // at least the landing
}

INSTANTIATE_TEST_SUITE_P(JointEngines, PlankBoxOnEngine,
                         testing::Values("box2d", "bullet", "ode", "mujoco"));

}  // namespace
}  // namespace impactbench
