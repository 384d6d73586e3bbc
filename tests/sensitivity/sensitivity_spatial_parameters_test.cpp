// Gains with respect to the contact parameters (μ and e as states with zero flow,
// MechanicalHybridModel's parameter_states): the end state's derivative by μ or e, predicted
// along the event-driven nominal through impacts, the slip flow and friction transitions, must
// match central differences of whole event-driven runs at μ ± ε (e ± ε) with errors shrinking
// as ε².
#include <gtest/gtest.h>

#include <iostream>
#include <memory>

#include "tests/support/lib/spatial_sensitivity_scenes.hpp"

namespace impactbench::sensitivity {
namespace {

using test_support::SpatialScene;

/// A sphere launched onto the ground at an angle with spin.
std::unique_ptr<SpatialScene> launched(double mu, double e, bool states) {
  return std::make_unique<SpatialScene>(
      test_support::sphere_over_ground(0.15, Eigen::Vector3d(2.5, -1.0, -1.0),
                                       Eigen::Vector3d(2.0, 5.0, -3.0), mu, e),
      states);
}

TEST(SpatialParameterGains, FrictionThroughImpactSlipAndRolling) {
  // e = 0: impact into slip, then slip → roll.
  const test_support::SceneFactory make = launched;
  test_support::expect_parameter_gain(make, 0.3, 0.0, 0, 0.5, {}, {},
                                      "friction gain, impact and roll");
}

TEST(SpatialParameterGains, RestitutionThroughABounce) {
  // e = 0.5, μ = 0.2: one bounce with a slip impulse, in the air at the end.
  const test_support::SceneFactory make = launched;
  test_support::expect_parameter_gain(make, 0.2, 0.5, 1, 0.12, {}, {}, "restitution gain, bounce");
  test_support::expect_parameter_gain(make, 0.2, 0.5, 0, 0.12, {}, {}, "friction gain, bounce");
}

}  // namespace
}  // namespace impactbench::sensitivity
