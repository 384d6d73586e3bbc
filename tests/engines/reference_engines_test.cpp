// Box2D and Bullet on the shipped analytical scenarios, through the same registry `impactbench
// run` uses. Where the engines' scheme gives the deviation in closed form (semi-implicit Euler
// with forces sampled at the step start) the expected value is derived and asserted. The other
// bounds are MEASURED REGRESSION BOUNDS, not physics: the deviation this test printed in a
// release build (Box2D 2.4.1, Bullet 3.24 double, dt = 1e-3, the scenarios' default) with a
// margin; they catch a change in the engines or the adapters, not a property of the model.
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
