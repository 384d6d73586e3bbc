// Newton's cradle under Moreau–Jean, e = 1, frictionless, no gravity: ball 1 hits two resting
// balls that touch each other. Both contacts are in the same one-step problem. With the
// complementarity r_i (ζ_i⁺ + e ζ_i⁻) = 0 on every active contact, the kinetic energy change
// ½ rᵀ J (v⁺ + v⁻) = ½ Σ r_i (ζ_i⁺ + ζ_i⁻) vanishes for e = 1: momentum and energy are conserved.
// But the law is simultaneous: for equal masses (m) and approach speed v0 it gives
//   ζ_12⁺ = v0, ζ_23⁺ = 0 (the touching pair had ζ_23⁻ = 0, so its restitution term is 0),
//   r_12 = 4 m v0 / 3, r_23 = 2 m v0 / 3,  v⁺ = (−1/3, 2/3, 2/3) v0,
// not the textbook (0, 0, v0), which is what a sequence of binary impacts gives; the scheme
// reproduces it when the balls are a small gap apart and the impacts fall in different steps.
#include <cmath>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "tests/support/lib/moreau_planar_worlds.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

constexpr double kRadius = 0.1;
constexpr double kSpeed = 1.0;

Eigen::VectorXd cradle(test_support::PlanarKind kind, double gap_23, double dt) {
  test_support::PlanarWorldSpec spec;
  spec.bodies = {test_support::disk("b1", kRadius, 1.0), test_support::disk("b2", kRadius, 1.0),
                 test_support::disk("b3", kRadius, 1.0)};
  spec.has_ground = false;
  spec.gravity = 0.0;
  spec.material = {0.0, 1.0};
  const auto world = test_support::make_planar_world(kind, spec);
  MoreauJeanOptions options;
  options.dt = dt;
  options.record_impulses = false;
  MoreauJeanStepper stepper(*world, options);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(9), v = Eigen::VectorXd::Zero(9);
  q(0) = -0.25;  // b1 0.05 m away from b2
  q(3) = 0.0;
  q(6) = 2 * kRadius + gap_23;
  v(0) = kSpeed;
  const auto result = stepper.simulate(q, v, {}, 0.1);
  EXPECT_TRUE(result.succeeded()) << result.message;
  EXPECT_NEAR(result.summary.energy_end, result.summary.energy_start,
              1e-9 * result.summary.energy_start);
  return result.final_state.v;
}

double momentum(const Eigen::VectorXd& v) {
  return v(0) + v(3) + v(6);
}
double kinetic(const Eigen::VectorXd& v) {
  return 0.5 * (v(0) * v(0) + v(3) * v(3) + v(6) * v(6));
}

class MoreauNewtonsCradle : public ::testing::TestWithParam<test_support::PlanarKind> {};

TEST_P(MoreauNewtonsCradle, SimultaneousImpactConservesAndSplits) {
  const Eigen::VectorXd v = cradle(GetParam(), 0.0, 1e-3);
  std::printf("cradle (touching): v = %.12f %.12f %.12f\n", v(0), v(3), v(6));
  EXPECT_NEAR(momentum(v), kSpeed, 1e-9 * kSpeed);
  EXPECT_NEAR(kinetic(v), 0.5 * kSpeed * kSpeed, 1e-9 * 0.5 * kSpeed * kSpeed);
  EXPECT_NEAR(v(0), -kSpeed / 3, 1e-9);
  EXPECT_NEAR(v(3), 2 * kSpeed / 3, 1e-9);
  EXPECT_NEAR(v(6), 2 * kSpeed / 3, 1e-9);
  for (int i : {1, 2, 4, 5, 7, 8}) EXPECT_NEAR(v(i), 0.0, 1e-12);
}

TEST_P(MoreauNewtonsCradle, SeparatedBallsGiveBinaryImpactSequence) {
  // 1 mm between b2 and b3, 0.1 ms steps: the two impacts are 1 ms apart, ten steps.
  const Eigen::VectorXd v = cradle(GetParam(), 1e-3, 1e-4);
  std::printf("cradle (1 mm apart): v = %.12f %.12f %.12f\n", v(0), v(3), v(6));
  EXPECT_NEAR(momentum(v), kSpeed, 1e-9 * kSpeed);
  EXPECT_NEAR(kinetic(v), 0.5 * kSpeed * kSpeed, 1e-9 * 0.5 * kSpeed * kSpeed);
  EXPECT_NEAR(v(0), 0.0, 1e-9);
  EXPECT_NEAR(v(3), 0.0, 1e-9);
  EXPECT_NEAR(v(6), kSpeed, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Systems, MoreauNewtonsCradle, test_support::all_planar_kinds(),
                         test_support::planar_kind_name);

}  // namespace
}  // namespace impactbench::engines::moreau_jean
