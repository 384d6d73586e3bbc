// Spatial sensitivity of cuboids landing on the ground (source C.2, D in 3-D): on a corner (one
// impact), on an edge (two corners at once: two micro-event orders, a conewise-constant gain)
// and flat (four corners at once). Tilts drawn with fixed seeds; the ε-tests of
// sensitivity_spatial_impact_test.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "lib/sensitivity/event_driven_nominal.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/support/lib/event_driven_runs.hpp"
#include "tests/support/lib/spatial_sensitivity_scenes.hpp"

namespace impactbench::sensitivity {
namespace {

using test_support::EventRuns;
using test_support::SpatialScene;

/// The centre height at which the lowest corner of the cuboid (half sizes 0.2, 0.15, 0.1) in
/// `orientation` is `clearance` above the ground.
double height_for(const Eigen::Quaterniond& orientation, double clearance) {
  const Eigen::Matrix3d R = orientation.toRotationMatrix();
  const Eigen::Vector3d half(0.2, 0.15, 0.1);
  // Lowest corner: −Σ |R_zj| h_j below the centre.
  return clearance + (R.row(2).cwiseAbs().transpose().cwiseProduct(half)).sum();
}

TEST(SpatialLanding, OnACornerFrictionless) {
  // A generic small tilt: one corner lowest; frictionless, e = 0. The run ends 15 ms after the
  // impact, before another corner comes down. (With μ = 0.5 the engine's own run stalls 4 ms
  // after the impact, CVODE's steps collapsing: an engine matter, not linearised here.)
  std::mt19937 rng(81);
  std::uniform_real_distribution<double> tilt(0.05, 0.15), sign(-1.0, 1.0);
  const double friction = 0.0;
  const Eigen::Quaterniond q =
      Eigen::AngleAxisd(std::copysign(tilt(rng), sign(rng)), Eigen::Vector3d::UnitX()) *
      Eigen::AngleAxisd(std::copysign(tilt(rng), sign(rng)), Eigen::Vector3d::UnitY()) *
      Eigen::Quaterniond::Identity();
  const Eigen::Vector3d v(0.3, -0.2, -1.0), w(0.5, -0.4, 0.3);
  const SpatialScene scene(
      test_support::cuboid_over_ground(height_for(q, 0.02), q, v, w, friction, 0.0));
  const double end = 0.035;
  EventRuns runs(scene.system(), scene.model(), end);
  const auto events = test_support::engine_micro_events(scene, runs, end);
  ASSERT_EQ(events.size(), 1u) << "friction " << friction;
  EXPECT_EQ(events[0].kind, GuardKind::kImpact);
  runs.directions = 6;
  test_support::expect_spatial_first_order(scene, runs, 83, "cuboid on a corner, frictionless");
}

TEST(SpatialLanding, FlatLandingIsRefusedWithOneClearMessage) {
  // Four corners at once, frictionless and inelastic: after any three micro impacts the fourth
  // corner is held by the others (its gap is a combination of theirs), its guard's rate is
  // round-off and no gain exists for it (C.37); the module says so instead of dividing by it.
  const SpatialScene scene(test_support::cuboid_over_ground(0.15, Eigen::Quaterniond::Identity(),
                                                            Eigen::Vector3d(0.0, 0.0, -1.0),
                                                            Eigen::Vector3d::Zero(), 0.0, 0.0));
  EventRuns runs(scene.system(), scene.model(), 0.2);
  const auto run = runs.run(scene.x0(), {});
  ASSERT_TRUE(run.succeeded()) << run.message;
  const NominalTrajectory nominal =
      nominal_from_event_run(scene.model(), scene.system(), run, {}, {}, 0.2);
  ASSERT_EQ(nominal.events.size(), 1u);
  ASSERT_EQ(nominal.events[0].micro_events.size(), 4u);
  try {
    const TrajectorySensitivity sensitivity(scene.model(), nominal);
    ADD_FAILURE() << "a flat landing was linearised";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("is no longer crossed transversally"), std::string::npos) << message;
    EXPECT_NE(message.find("redundant contact"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace impactbench::sensitivity
