// Rocking block (Housner) under Moreau–Jean, e = 0 and μ large: a slender box rotating about
// one bottom corner lands flat and continues about the other corner. Angular momentum about the
// new corner O' is conserved through the impact (the impulse acts at O'); for a box of width b,
// height H, mass m, upright at impact and rotating with ω about O:
//   before: L_O' = I_G ω + m (G − O') × v_G = m ω [(b² + H²)/12 + (H² − b²)/4],
//   after:  L_O' = I_O' ω' = m ω' (b² + H²)/3,
// so ω'/ω = 1 − (3/2) b²/(b² + H²) = 1 − 1.5 sin²α with α = atan(b/H), the angle between the
// vertical and the diagonal (full width over full height).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "tests/support/lib/moreau_planar_worlds.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

constexpr double kGravity = 9.81;

struct Impact {
  double omega_before = 0.0;
  double omega_after = 0.0;
  bool found = false;
};

// Released from rest turned by `tilt` (< 0: left corner lifted) about its bottom-right corner;
// returns ω across the step in which the bottom-left corner (feature 0) first takes an impulse.
Impact rock(test_support::PlanarKind kind, double width, double height, double tilt, double dt) {
  test_support::PlanarWorldSpec spec;
  spec.bodies = {test_support::box("block", width, height, 1.0)};
  spec.gravity = kGravity;
  spec.material = {10.0, 0.0};
  const auto world = test_support::make_planar_world(kind, spec);
  MoreauJeanOptions options;
  options.dt = dt;
  options.record_impulses = false;
  MoreauJeanStepper stepper(*world, options);
  const Eigen::Vector2d pivot(width / 2, 0.0);
  const Eigen::Vector2d centre =
      pivot + Eigen::Rotation2Dd(tilt) * Eigen::Vector2d(-width / 2, height / 2);
  MoreauJeanState state{0.0, Eigen::Vector3d(centre.x(), centre.y(), tilt),
                        Eigen::Vector3d::Zero()};
  Impact impact;
  while (!impact.found && state.t < 2.0) {
    const double omega_previous = state.v(2);
    const StepReport report = stepper.step(state, {});
    EXPECT_TRUE(report.advanced) << report.message();
    if (!report.advanced) break;
    for (const auto& c : report.impulses())
      if (c.point.x() < 0.0 && c.r_n > 0.0) impact = {omega_previous, state.v(2), true};
  }
  return impact;
}

class MoreauRockingBlock : public ::testing::TestWithParam<test_support::PlanarKind> {};

TEST_P(MoreauRockingBlock, HousnerAngularVelocityRatio) {
  const double width = 0.2, height = 1.0;
  const double alpha = std::atan(width / height);
  const double expected = 1.0 - 1.5 * std::sin(alpha) * std::sin(alpha);
  // The step's gravity impulse changes L_O' by m g (b/2) h: a relative error ≈ 6 h here.
  std::vector<double> errors;
  for (double dt : {1e-4, 2e-5}) {
    const Impact impact = rock(GetParam(), width, height, -0.05, dt);
    ASSERT_TRUE(impact.found);
    ASSERT_GT(impact.omega_before, 0.0);  // falling back counterclockwise about the right corner
    const double ratio = impact.omega_after / impact.omega_before;
    std::printf("rocking block dt %.0e: omega %.6f -> %.6f, ratio %.6f, Housner %.6f\n", dt,
                impact.omega_before, impact.omega_after, ratio, expected);
    EXPECT_NEAR(ratio, expected, 1e-3) << dt;
    errors.push_back(std::abs(ratio - expected));
  }
  // First order: a step 5 times smaller gives an error about 5 times smaller.
  EXPECT_GE(errors[0] / errors[1], 4.0);
  EXPECT_LE(errors[0] / errors[1], 6.0);
}

INSTANTIATE_TEST_SUITE_P(Systems, MoreauRockingBlock, test_support::all_planar_kinds(),
                         test_support::planar_kind_name);

}  // namespace
}  // namespace impactbench::engines::moreau_jean
