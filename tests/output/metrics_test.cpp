// The metrics on synthetic trajectories whose errors are known in closed form.
#include <cmath>

#include <gtest/gtest.h>

#include "lib/metrics/ballistic_events.hpp"
#include "lib/metrics/contact_criteria.hpp"
#include "lib/metrics/energy_drift.hpp"
#include "lib/metrics/trajectory_error.hpp"

namespace impactbench::metrics {
namespace {

constexpr double kG = 9.81;

TEST(TrajectoryError, ConstantOffsetGivesOffsetTimesDuration) {
  Signal reference, shifted;
  for (int i = 0; i <= 1000; ++i) {
    const double t = 2.0 * i / 1000;
    reference.times.push_back(t);
    reference.values.push_back(Eigen::Vector2d(std::sin(t), std::cos(t)));
  }
  // Sampled on another grid, offset by (0.003, 0.004): ‖e‖ = 0.005 everywhere.
  for (int i = 0; i <= 333; ++i) {
    const double t = 2.0 * i / 333;
    shifted.times.push_back(t);
    shifted.values.push_back(Eigen::Vector2d(std::sin(t) + 0.003, std::cos(t) + 0.004));
  }
  const TrajectoryError e = trajectory_error(shifted, reference);
  // Linear interpolation of the reference adds at most h²/8 ≈ 5e-7 to each component.
  EXPECT_NEAR(e.linf, 0.005, 1e-6);
  EXPECT_NEAR(e.l1, 0.005 * 2.0, 2e-6);
}

TEST(TrajectoryError, LinearlyGrowingErrorIntegratesToHalfTSquared) {
  Signal reference, drifting;
  for (int i = 0; i <= 100; ++i) {
    const double t = 0.01 * i;
    reference.times.push_back(t);
    reference.values.push_back(Eigen::VectorXd::Constant(1, 1.0));
    drifting.times.push_back(t);
    drifting.values.push_back(Eigen::VectorXd::Constant(1, 1.0 + 0.3 * t));
  }
  const TrajectoryError e = trajectory_error(drifting, reference);
  EXPECT_NEAR(e.l1, 0.15, 1e-12);  // ∫0^1 0.3 t dt, exact for the trapezoidal rule
  EXPECT_NEAR(e.linf, 0.3, 1e-12);
}

TEST(TrajectoryError, RejectsMismatchedSizes) {
  Signal a{{0.0}, {Eigen::Vector2d::Zero()}}, b{{0.0}, {Eigen::Vector3d::Zero()}};
  EXPECT_THROW(trajectory_error(a, b), std::invalid_argument);
}

TEST(Apex, ParabolaRefinementRecoversTheExactApexBetweenSamples) {
  // Ballistic flight from y = 0 with v = 3 m/s: apex 9/(2g) at t = 3/g, sampled coarsely.
  std::vector<double> t, y;
  for (int i = 0; i <= 60; ++i) {
    const double s = 0.0107 * i;
    t.push_back(s);
    y.push_back(3.0 * s - 0.5 * kG * s * s);
  }
  const auto apexes = apex_heights(t, y);
  ASSERT_EQ(apexes.size(), 1u);
  EXPECT_NEAR(apexes[0].height, 9.0 / (2 * kG), 1e-12);
  EXPECT_NEAR(apexes[0].t, 3.0 / kG, 1e-12);
}

TEST(ImpactTimes, DetectsEachVelocityReversal) {
  const std::vector<double> t{0, 1, 2, 3, 4, 5};
  const std::vector<double> vy{-1, -2, 1.5, 0.5, -1, 0.8};
  const auto impacts = impact_times(t, vy);
  ASSERT_EQ(impacts.size(), 2u);
  EXPECT_DOUBLE_EQ(impacts[0], 2.0);
  EXPECT_DOUBLE_EQ(impacts[1], 5.0);
}

TEST(StopPoint, InterpolatesTheVelocityZero) {
  // v = 2 − 4.905 t reaches 0 at t* = 2/4.905; x = 2t − 2.4525 t².
  std::vector<double> t, x, v;
  for (int i = 0; i <= 100; ++i) {
    const double s = 0.01 * i;
    t.push_back(s);
    v.push_back(std::max(0.0, 2.0 - 4.905 * s));
    const double sc = std::min(s, 2.0 / 4.905);
    x.push_back(2.0 * sc - 2.4525 * sc * sc);
  }
  const auto stop = stop_point(t, x, v, 0.0);
  ASSERT_TRUE(stop.has_value());
  // Constant deceleration: the extrapolation is exact for the time and the distance.
  EXPECT_NEAR(stop->t, 2.0 / 4.905, 1e-12);
  EXPECT_NEAR(stop->position, 4.0 / (2 * 4.905), 1e-12);
}

TEST(StopPoint, AStopSampledAtItsEventIsFoundThoughRoundOffPutsItPastTheSample) {
  // Samples at 0.39 and 0.40 s and at the stop event 0.4077471967380222 s of a block
  // decelerating at 4.905 m/s² from 2 m/s (an event-driven run's figures): the extrapolated
  // stop lies 5e-17 s past the last sample, by round-off. Without a round-off allowance the
  // threshold's linear interpolation put it 2 µs early.
  const std::vector<double> t = {0.39, 0.4, 0.4077471967380222};
  const std::vector<double> v = {0.08704999999999896, 0.03799999999999894, 2.220446049250313e-16};
  const std::vector<double> x = {0.406975, 0.4076, 0.40774719673802284};
  const auto stop = stop_point(t, x, v, 1e-5);
  ASSERT_TRUE(stop.has_value());
  EXPECT_NEAR(stop->t, 2.0 / 4.905, 1e-12);
}

TEST(ContactCriteria, ExactSlidingContactViolatesNothing) {
  engines::ContactSample c;
  c.friction = 0.5;
  c.impulse_n = 0.2;
  c.velocity_n = 0.0;
  c.velocity_t = Eigen::Vector2d(0.6, 0.8);              // sliding at 1 m/s
  c.impulse_t = -0.5 * 0.2 * Eigen::Vector2d(0.6, 0.8);  // −μ λ_n ζ_t/‖ζ_t‖
  const ContactCriteria k = contact_criteria(c, 1e-9);
  EXPECT_NEAR(k.signorini, 0.0, 1e-15);
  EXPECT_NEAR(k.friction_cone, 0.0, 1e-15);
  EXPECT_NEAR(k.max_dissipation, 0.0, 1e-15);
  EXPECT_NEAR(k.complementarity, 0.0, 1e-15);
}

TEST(ContactCriteria, KnownViolationsAreMeasured) {
  engines::ContactSample c;
  c.friction = 0.5;
  c.impulse_n = 0.2;
  c.velocity_n = 0.3;  // separating while pushing: Signorini 0.06
  c.velocity_t = Eigen::Vector2d(1.0, 0.0);
  c.impulse_t = Eigen::Vector2d(-0.15, 0.0);  // outside the cone by 0.05, too large by 0.05
  c.gap = -0.002;
  const ContactCriteria k = contact_criteria(c, 1e-9);
  EXPECT_NEAR(k.signorini, 0.06, 1e-15);
  EXPECT_NEAR(k.friction_cone, 0.05, 1e-15);
  EXPECT_NEAR(k.max_dissipation, 0.05, 1e-15);
  // λ_n(ζ_n + μ‖ζ_t‖) + λ_tᵀζ_t = 0.2 (0.3 + 0.5) − 0.15 = 0.01
  EXPECT_NEAR(k.complementarity, 0.01, 1e-15);
  EXPECT_NEAR(k.penetration, 0.002, 1e-15);
}

TEST(EnergyDrift, MeasuresRelativeChangeAndLargestRise) {
  const EnergyDrift d = energy_drift({10.0, 9.0, 9.5, 8.0});
  EXPECT_NEAR(d.relative_change, -0.2, 1e-15);
  EXPECT_NEAR(d.max_rise, 0.5, 1e-15);
}

}  // namespace
}  // namespace impactbench::metrics
