// Sensitivity of the bouncing ball (scenario bouncing_ball: e = 0.9, released from rest with the
// centre 0.9 m above the contact height): jump gain = classical saltation matrix, and the
// first-order prediction's error shrinks like ε² through two impacts.
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/support/lib/hybrid_reference_simulator.hpp"
#include "tests/support/lib/point_mass_on_slope.hpp"
#include "tests/support/lib/sensitivity_convergence.hpp"

namespace impactbench::sensitivity {
namespace {

using test_support::PointMassOnSlope;

constexpr double kGravity = 9.81;
constexpr double kRestitution = 0.9;
constexpr double kDrop = 0.9;  // height − radius [m]

class BouncingBallSensitivity : public ::testing::Test {
 protected:
  BouncingBallSensitivity()
      : system_({1.0, kGravity, 0.0, 0.0, kRestitution}),
        system_ad_({1.0, kGravity, 0.0, 0.0, kRestitution}),
        model_(system_, system_ad_) {
    setup_.model = &model_;
    setup_.mode0 = {ContactPhase::kOpen};
    setup_.x0 = Eigen::Vector4d(0.0, kDrop, 0.3, 0.0);
    setup_.t0 = 0.0;
    setup_.t_end = 1.5;
    setup_.options.impact_phase = {ContactPhase::kOpen};
  }

  PointMassOnSlope<double> system_;
  PointMassOnSlope<AutoDiff> system_ad_;
  MechanicalHybridModel model_;
  test_support::ConvergenceSetup setup_;
};

TEST_F(BouncingBallSensitivity, NominalImpactTimesMatchTheClosedForm) {
  const auto run = test_support::simulate_reference(model_, setup_.mode0, setup_.x0, {}, 0.0,
                                                    setup_.t_end, {}, setup_.options);
  ASSERT_EQ(run.events.size(), 2u);
  const double t1 = std::sqrt(2 * kDrop / kGravity);
  const double t2 = t1 + 2 * kRestitution * kGravity * t1 / kGravity;
  EXPECT_NEAR(run.events[0].time, t1, 1e-12);
  EXPECT_NEAR(run.events[1].time, t2, 1e-12);
}

// Ξ = R + (f⁺ − R f⁻) n_γᵀ / (n_γᵀ f⁻) with R = diag(1, 1, 1, −e), n_γ = ∂y/∂x, built here from
// the free-fall closed form, not from the model.
TEST_F(BouncingBallSensitivity, JumpGainIsTheClassicalSaltationMatrix) {
  const auto run = test_support::simulate_reference(model_, setup_.mode0, setup_.x0, {}, 0.0,
                                                    setup_.t_end, {}, setup_.options);
  const TrajectorySensitivity sensitivity(
      model_,
      test_support::nominal_from_run(run, setup_.mode0, setup_.x0, {}, {}, 0.0, setup_.t_end));
  ASSERT_EQ(sensitivity.events().size(), 2u);
  const double vy = -std::sqrt(2 * kGravity * kDrop);  // speed at the first impact
  const Eigen::Vector4d f_minus(0.3, vy, 0.0, -kGravity);
  const Eigen::Vector4d f_plus(0.3, -kRestitution * vy, 0.0, -kGravity);
  const Eigen::Matrix4d R = Eigen::Vector4d(1, 1, 1, -kRestitution).asDiagonal();
  const Eigen::RowVector4d n(0, 1, 0, 0);
  const Eigen::Matrix4d saltation = R + (f_plus - R * f_minus) * n / n.dot(f_minus);
  const ComposedGain gain = sensitivity.events()[0].gain_of_order({0});
  EXPECT_LT((gain.Gz - saltation).lpNorm<Eigen::Infinity>(), 1e-9) << gain.Gz;
  EXPECT_EQ(gain.Gv.norm(), 0.0);  // the gap does not depend on the input
  // The jump gain scales perturbations like a reflection: ẏ⁺ perturbation = −e (…).
  EXPECT_NEAR(gain.Gz(3, 3), -kRestitution, 1e-12);
}

TEST_F(BouncingBallSensitivity, PredictionErrorShrinksLikeEpsilonSquared) {
  const auto nominal_run = test_support::nominal_run_with_event_probes(setup_, 61);
  const TrajectorySensitivity sensitivity(model_, test_support::nominal_of(setup_, nominal_run));
  std::mt19937 rng(7);
  std::vector<test_support::PerturbationDirection> directions;
  for (int k = 0; k < 20; ++k) directions.push_back(test_support::random_direction(setup_, rng));
  test_support::expect_second_order(setup_, nominal_run, sensitivity, directions, "bouncing_ball");
}

// Control experiment for the error measure: the probes around the impacts do fall between the
// nominal and the perturbed impact, where the raw states straddle the velocity jump (error O(1),
// not O(ε)); compared like with like (the perturbed ball's flight extended across its impact)
// the error there is O(ε²) like everywhere else.
TEST_F(BouncingBallSensitivity, SamplesBetweenImpactsAreComparedOnExtendedTrajectories) {
  const auto nominal_run = test_support::nominal_run_with_event_probes(setup_, 61);
  const TrajectorySensitivity sensitivity(model_, test_support::nominal_of(setup_, nominal_run));
  test_support::PerturbationDirection d;
  d.z0 = Eigen::Vector4d(0.0, 0.6, 0.0, 0.8);  // higher and rising: both impacts come later
  d.v0 = d.v1 = Eigen::VectorXd::Zero(1);
  const auto z = sensitivity.perturbation(d.z0, d.input(), nominal_run.times);
  const double eps = 1e-3;
  const double raw = test_support::prediction_errors(setup_, nominal_run, z, d, {eps},
                                                     test_support::Comparison::kRaw)[0];
  const double spread = test_support::prediction_errors(setup_, nominal_run, z, d, {eps})[0];
  const double impact_speed = std::sqrt(2 * kGravity * kDrop);
  EXPECT_GT(raw, impact_speed);  // (1 + e) × speed across the first impact
  EXPECT_LT(spread, 1e3 * eps * eps);
  std::cout << "[bouncing_ball] eps = 1e-3, max error with raw states " << raw
            << ", on extended trajectories " << spread << "\n";
}

}  // namespace
}  // namespace impactbench::sensitivity
