// The activation rule of the Moreau–Jean stepper against an independent scalar Moreau–Jean
// computation of the bouncing ball, written here: same trajectory step for step, for
// γ = 1/2 and γ = 1, and the default rule predicts the gap at the θ-point (γ = θ).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "tests/support/lib/moreau_planar_worlds.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

constexpr double kGravity = 9.81;
constexpr double kRadius = 0.1;
constexpr double kHeight = 1.0;
constexpr double kRestitution = 0.9;
constexpr double kStep = 5e-3;
constexpr double kDuration = 10.0;  // past the accumulation point t∞ ≈ 8.13 s

struct BallNode {
  double y = 0.0;  // centre height [m]
  double v = 0.0;  // vertical velocity [m/s]
};

// The θ-method for a ball of unit mass over a ground at y = 0 with Moreau's impact law and
// Newton restitution at velocity level: free velocity v_free = v_k − h g (gravity is constant);
// the contact is active when the gap predicted γh ahead is ≤ τ; then
// 0 ≤ r ⊥ v_{k+1} + e min(v_k, 0) ≥ 0 with v_{k+1} = v_free + r, i.e.
// v_{k+1} = max(v_free, −e min(v_k, 0)); finally y_{k+1} = y_k + h ((1 − θ) v_k + θ v_{k+1}).
std::vector<BallNode> scalar_moreau_jean(double theta, double gamma, double tolerance) {
  std::vector<BallNode> nodes{{kHeight, 0.0}};
  const long steps = std::lround(kDuration / kStep);
  for (long k = 0; k < steps; ++k) {
    const BallNode& n = nodes.back();
    const double v_free = n.v - kStep * kGravity;
    const bool active = (n.y - kRadius) + gamma * kStep * n.v <= tolerance;
    const double v_next = active ? std::max(v_free, -kRestitution * std::min(n.v, 0.0)) : v_free;
    nodes.push_back({n.y + kStep * ((1 - theta) * n.v + theta * v_next), v_next});
  }
  return nodes;
}

std::vector<BallNode> stepper_run(const MoreauJeanOptions& options) {
  test_support::PlanarWorldSpec spec;
  spec.bodies = {test_support::disk("ball", kRadius, 1.0)};
  spec.gravity = kGravity;
  spec.material = {0.0, kRestitution};
  const auto world =
      test_support::make_planar_world(test_support::PlanarKind::kProjectSystem, spec);
  MoreauJeanStepper stepper(*world, options);
  // Whole steps of exactly h (simulate would shorten the last one by the round-off of t).
  MoreauJeanState state{0.0, Eigen::Vector3d(0, kHeight, 0), Eigen::Vector3d::Zero()};
  std::vector<BallNode> nodes{{state.q(1), state.v(1)}};
  const long steps = std::lround(kDuration / kStep);
  for (long k = 0; k < steps; ++k) {
    const StepReport report = stepper.step(state, {});
    EXPECT_TRUE(report.advanced && report.statistics.converged) << report.message();
    nodes.push_back({state.q(1), state.v(1)});
  }
  return nodes;
}

struct Difference {
  double height = 0.0;
  double velocity = 0.0;
  int impacts = 0;  // steps of the independent run with an impulse (so the test is not vacuous)
};

Difference compare(const std::vector<BallNode>& ours, const std::vector<BallNode>& reference) {
  EXPECT_EQ(ours.size(), reference.size());
  Difference d;
  for (std::size_t k = 0; k < std::min(ours.size(), reference.size()); ++k) {
    d.height = std::max(d.height, std::abs(ours[k].y - reference[k].y));
    d.velocity = std::max(d.velocity, std::abs(ours[k].v - reference[k].v));
    if (k > 0 && reference[k].v > reference[k - 1].v) ++d.impacts;
  }
  return d;
}

class MoreauActivation : public ::testing::TestWithParam<double> {};

TEST_P(MoreauActivation, BallMatchesAnIndependentScalarComputationStepForStep) {
  const double gamma = GetParam();
  MoreauJeanOptions options;
  options.dt = kStep;
  options.theta = 0.5;
  options.activation_horizon = gamma;
  options.activation_tolerance = 0.0;
  const Difference d = compare(stepper_run(options), scalar_moreau_jean(0.5, gamma, 0.0));
  std::printf("gamma = %g: max height difference %.3g m, velocity %.3g m/s over %g s\n", gamma,
              d.height, d.velocity, kDuration);
  EXPECT_GT(d.impacts, 20);
  EXPECT_LE(d.height, 1e-12);
  EXPECT_LE(d.velocity, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Horizons, MoreauActivation, ::testing::Values(0.5, 1.0));

// The default rule predicts the gap at the θ-point: γ = θ (θ = 1/2 and θ = 1), with the
// default tolerance.
TEST(MoreauActivationDefault, PredictsTheGapAtTheThetaPoint) {
  for (const double theta : {0.5, 1.0}) {
    MoreauJeanOptions options;
    options.dt = kStep;
    options.theta = theta;
    const Difference d = compare(stepper_run(options),
                                 scalar_moreau_jean(theta, theta, options.activation_tolerance));
    EXPECT_LE(d.height, 1e-12) << "theta = " << theta;
    EXPECT_LE(d.velocity, 1e-12) << "theta = " << theta;
  }
}

// The two rules really differ on this ball (else the tests above could not tell them apart).
TEST(MoreauActivationDefault, TheHorizonsGiveDifferentTrajectories) {
  const Difference d =
      compare(scalar_moreau_jean(0.5, 0.5, 0.0), scalar_moreau_jean(0.5, 1.0, 0.0));
  EXPECT_GT(d.height, 1e-3);
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
