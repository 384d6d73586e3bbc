// Spatial sensitivity of a recorded cube toss (the cube_toss scenario, whose default release
// state is one of the DAIR Lab tosses of data/cube_toss): its first 0.2 s hold three bounces on
// single corners with slip impulses (e = 0.125, μ = 0.3), before the fourth impact and the Zeno
// rest that cannot be linearised. The prediction is checked against central differences of the
// event engine (state and contact parameters) and against perturbed runs along the trajectory.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "lib/engines/system_builder.hpp"
#include "tests/support/lib/spatial_sensitivity_scenes.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::sensitivity {
namespace {

using test_support::EventRuns;
using test_support::SpatialScene;

constexpr double kEnd = 0.2;  // after the third bounce (0.192 s), before the fourth (0.218 s)

std::unique_ptr<SpatialScene> recorded_toss(double friction, double restitution, bool states) {
  const scenario::Scenario toss = scenario::load_scenario_by_name(
      "cube_toss", {{"friction", friction}, {"restitution", restitution}});
  return std::make_unique<SpatialScene>(engines::spatial_spec(toss), states);
}

TEST(SensitivityCubeToss, ThreeBouncesOnCornersArePredictedToSecondOrder) {
  const auto scene = recorded_toss(0.3, 0.125, false);
  EventRuns runs(scene->system(), scene->model(), kEnd);
  const auto run = runs.run(scene->x0(), {});
  ASSERT_TRUE(run.succeeded()) << run.message;
  ASSERT_EQ(run.events.size(), 3u);
  for (const auto& event : run.events) {
    EXPECT_EQ(event.kind, engines::event_driven::EventKind::kImpact);
    EXPECT_EQ(event.to_mode, engines::event_driven::ContactMode::kOpen) << "a bounce";
    EXPECT_GT(event.impulse_t.norm(), 0.0) << "with friction";
  }
  runs.directions = 6;
  test_support::expect_spatial_first_order(*scene, runs, 97, "recorded cube toss, three bounces");
}

TEST(SensitivityCubeToss, FrictionAndRestitutionGainsMatchWholeRuns) {
  const test_support::SceneFactory make = recorded_toss;
  test_support::expect_parameter_gain(make, 0.3, 0.125, 0, kEnd, {}, {},
                                      "recorded cube toss, friction");
  test_support::expect_parameter_gain(make, 0.3, 0.125, 1, kEnd, {}, {},
                                      "recorded cube toss, restitution");
}

}  // namespace
}  // namespace impactbench::sensitivity
