// Box2D and Bullet on the shipped analytical scenarios, through the same registry `impactbench
// run` uses. Where the engines' scheme gives the deviation in closed form (semi-implicit Euler
// with forces sampled at the step start) the expected value is derived and asserted. The other
// bounds are MEASURED REGRESSION BOUNDS, not physics: the deviation this test printed in a
// release build (Box2D 2.4.1, Bullet 3.24 double, dt = 1e-3, the scenarios' default) with a
// margin; they catch a change in the engines or the adapters, not a property of the model.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/reference_engine_runs.hpp"
#include "tools/engines/fixed_step/reference_scene.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

using test_support::named;
using test_support::run_and_measure;

class ReferenceEngine : public testing::TestWithParam<std::string> {};

TEST_P(ReferenceEngine, InclineAboveTheFrictionAngleAcceleratesAtGSinMinusMuCos) {
  // tan 30° > μ = 0.5: the unpushed block slides from rest with a = g (sin α − μ cos α); the
  // final speed after 2 s measures a (semi-implicit Euler is exact for a constant force).
  // Measured regression bounds (release build, this test): relative error Box2D 5e-7 (float
  // rounding), Bullet 1.4e-3 (its friction anchors resist the first steps of sliding).
  const auto errors = run_and_measure(GetParam(), "incline", {{"angle", 30.0}, {"push_rate", 0.0}});
  const double a = 9.81 * (std::sin(M_PI / 6) - 0.5 * std::cos(M_PI / 6));
  const double relative = std::abs(named(errors, "slip_speed_error")) / (a * 2.0);
  EXPECT_LT(relative, GetParam() == "box2d" ? 1e-5 : 3e-3);
}

INSTANTIATE_TEST_SUITE_P(BothEngines, ReferenceEngine, testing::Values("box2d", "bullet"));

TEST(ReferenceEngines, UnrepresentableScenariosGiveAClearError) {
  const auto spin = scenario::load_scenario_by_name("sphere_spin");
  engines::SettingsRequest request;
  request.duration = 0.1;
  const engines::RunOptions options = engines::resolve_run_options("box2d", spin, request);
  // The scenario file does not list box2d; the registry refuses before running anything.
  try {
    adapters::run_engine("box2d", spin, options);
    FAIL() << "box2d ran a spatial scenario";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be run by engine 'box2d'"), std::string::npos);
  }
  // The adapter itself also refuses a spatial scene when asked directly.
  const auto* box2d = adapters::find_engine("box2d");
  ASSERT_NE(box2d, nullptr);
  EXPECT_THROW(box2d->run(spin, options), adapters::UnsupportedScene);
}

TEST(ReferenceEngines, UnknownSettingsNameTheValidKeys) {
  const auto s = scenario::load_scenario_by_name("sliding_block");
  engines::SettingsRequest request;
  request.duration = 0.01;
  request.options = {{"velocity_iteration", "3"}};
  try {
    engines::resolve_run_options("box2d", s, request);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("velocity_iterations"), std::string::npos);
  }
  request.options = {{"solver", "lemke"}};
  EXPECT_THROW(engines::resolve_run_options("bullet", s, request), std::invalid_argument);
}

}  // namespace
}  // namespace impactbench

namespace impactbench {
namespace {

// Two equal disks, one struck head-on by the other at v0 with Newton's restitution e = 0.5: the
// struck one leaves at (1 + e)/2 v0 = 0.75 v0 and the striker keeps (1 − e)/2 v0. A single
// two-body contact is solved exactly by every engine's velocity-level impulse, so the bound is
// round-off (float velocities in Box2D: 1e-6 of 1 m/s). ODE's constraint force mixing softens
// the contact: its LCP row is (W + CFM/h) λ = (1 + e) v0 with W = 1/m₁ + 1/m₂, so the impulse is
// that much smaller (CFM 1e-8 at h = 1e-3: 5e-6 relative). Bullet combines materials by
// product: before each body got √e, a body–body pair got e² and the struck disk left at
// 0.625 v0.
TEST(ReferenceEngines, TwoDiskImpactGivesEachEngineTheScenariosRestitution) {
  const auto s =
      scenario::load_scenario_by_name("newtons_cradle", {{"count", 2.0}, {"restitution", 0.5}});
  for (const std::string engine : {"box2d", "bullet", "ode"}) {
    SCOPED_TRACE(engine);
    engines::SettingsRequest request;
    request.duration = 0.1;  // the impact comes at gap/v0 = 0.01 s
    const auto options = engines::resolve_run_options(engine, s, request);
    const auto run = adapters::run_engine(engine, s, options);
    const double softness = engine == "ode" ? engines::setting_number(options.settings, "cfm") /
                                                  engines::setting_number(options.settings, "dt")
                                            : 0.0;
    const double impulse = 1.5 / (2.0 + softness);  // (1 + e) v0 / (W + CFM/h), m = 1 kg
    const auto& names = run.trajectory.velocity_names;
    const auto& v = run.trajectory.samples.back().v;
    const auto speed = [&](const std::string& column) {
      const auto at = std::find(names.begin(), names.end(), column);
      EXPECT_NE(at, names.end()) << column;
      return at == names.end() ? 0.0 : v[at - names.begin()];
    };
    const double round_off = engine == "box2d" ? 1e-6 : 1e-12;  // float or double velocities
    EXPECT_NEAR(speed("ball1.vx"), impulse, round_off);
    EXPECT_NEAR(speed("ball0.vx"), 1.0 - impulse, round_off);
  }
}

}  // namespace
}  // namespace impactbench
