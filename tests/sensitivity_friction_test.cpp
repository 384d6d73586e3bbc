// Sensitivity through friction-mode changes: the sliding block (scenario sliding_block: slip →
// stick, guard ζ_t = 0) and the block on an incline pushed down the slope by u = c t (scenario
// incline: stick → slip, guard μλ_n + λ_t = 0, which depends on the input). Point-mass models
// of both scenarios (no tipping: the scenario files state it does not occur).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/test_utilities/hybrid_reference_simulator.hpp"
#include "tests/test_utilities/point_mass_on_slope.hpp"
#include "tests/test_utilities/sensitivity_convergence.hpp"

namespace impactbench::sensitivity {
namespace {

using test_utilities::PointMassOnSlope;
using test_utilities::PointMassOnSlopeParameters;

constexpr double kGravity = 9.81;
constexpr double kFriction = 0.5;

/// A point-mass scenario: model, nominal run on sample times away from its events, sensitivity.
class FrictionCase {
 public:
  FrictionCase(const PointMassOnSlopeParameters& parameters, HybridMode mode0,
               const Eigen::Vector4d& x0, InputFunction input, InputFunction input_rate,
               double t_end)
      : system_(parameters), system_ad_(parameters), model_(system_, system_ad_) {
    setup_.model = &model_;
    setup_.mode0 = std::move(mode0);
    setup_.x0 = x0;
    setup_.input = std::move(input);
    setup_.input_rate = std::move(input_rate);
    setup_.t_end = t_end;
    setup_.options.impact_phase = {ContactPhase::kStick};
    // The motion is polynomial of degree ≤ 3 in t in every mode, which RK4 integrates exactly:
    // large steps only reduce round-off.
    setup_.options.max_step = 1e-2;
    const auto probe = test_utilities::simulate_reference(
        model_, setup_.mode0, setup_.x0, setup_.input, 0.0, t_end, {}, setup_.options);
    for (const auto& e : probe.events) event_times_.push_back(e.time);
    const auto times = test_utilities::sample_times_away_from(0.0, t_end, 81, event_times_, 0.02);
    nominal_run_ = test_utilities::simulate_reference(model_, setup_.mode0, setup_.x0, setup_.input,
                                                      0.0, t_end, times, setup_.options);
    sensitivity_ = std::make_unique<TrajectorySensitivity>(
        model_, test_utilities::nominal_from_run(nominal_run_, setup_.mode0, setup_.x0,
                                                 setup_.input, setup_.input_rate, 0.0, t_end));
  }

  void expect_epsilon_squared(const char* label, unsigned seed) const {
    std::mt19937 rng(seed);
    double lo = 1e9, hi = 0.0;
    for (int k = 0; k < 20; ++k) {
      const auto direction = test_utilities::random_direction(setup_, rng);
      const auto ratios = test_utilities::error_ratios(setup_, nominal_run_, *sensitivity_,
                                                       direction, {1e-3, 1e-4, 1e-5});
      for (const double r : ratios) {
        EXPECT_GE(r, 3.0) << label << " direction " << k;
        EXPECT_LE(r, 5.0) << label << " direction " << k;
        lo = std::min(lo, r);
        hi = std::max(hi, r);
      }
    }
    std::cout << "[" << label
              << "] error ratio e(eps)/e(eps/2), eps = 1e-3..1e-5, 20 directions: " << lo << " .. "
              << hi << "\n";
  }

  const test_utilities::ReferenceRun& nominal_run() const { return nominal_run_; }
  const TrajectorySensitivity& sensitivity() const { return *sensitivity_; }
  const MechanicalHybridModel& model() const { return model_; }

 private:
  PointMassOnSlope<double> system_;
  PointMassOnSlope<AutoDiff> system_ad_;
  MechanicalHybridModel model_;
  test_utilities::ConvergenceSetup setup_;
  std::vector<double> event_times_;
  test_utilities::ReferenceRun nominal_run_;
  std::unique_ptr<TrajectorySensitivity> sensitivity_;
};

// --- sliding_block: v0 = 2 m/s on flat ground, μ = 0.5 -------------------------------------
constexpr double kSlideSpeed = 2.0;

FrictionCase sliding_block() {
  return FrictionCase({1.0, kGravity, 0.0, kFriction, 0.0}, {ContactPhase::kSlipPositive},
                      Eigen::Vector4d(0.0, 0.0, kSlideSpeed, 0.0), {}, {}, 1.0);
}

TEST(SlidingBlockSensitivity, StopsAtTheAnalyticTimeAndPlace) {
  const FrictionCase c = sliding_block();
  ASSERT_EQ(c.nominal_run().events.size(), 1u);
  EXPECT_EQ(c.nominal_run().events[0].event.kind, GuardKind::kSlipToStick);
  EXPECT_NEAR(c.nominal_run().events[0].time, kSlideSpeed / (kFriction * kGravity), 1e-12);
  EXPECT_NEAR(c.nominal_run().final_state(0),
              kSlideSpeed * kSlideSpeed / (2 * kFriction * kGravity), 1e-12);
}

// Stop distance v0²/(2μg): ∂x_end/∂v0 = v0/(μg), ∂x_end/∂x0 = 1, and the block is at rest.
// Input perturbation δu (constant force along x) while sliding: the deceleration becomes
// μg − δu/m, so ∂x_end/∂δu = v0²/(2 m (μg)²).
TEST(SlidingBlockSensitivity, EndPointMatrixMatchesTheClosedForm) {
  const FrictionCase c = sliding_block();
  const InputBasis constant = [](double) { return Eigen::MatrixXd::Identity(1, 1); };
  const EndPointSensitivity end = c.sensitivity().end_point_sensitivity(constant);
  const double a = kFriction * kGravity;
  EXPECT_NEAR(end.state(0, 0), 1.0, 1e-10);
  EXPECT_NEAR(end.state(0, 2), kSlideSpeed / a, 1e-10);
  EXPECT_NEAR(end.state.row(2).norm(), 0.0, 1e-10);
  EXPECT_NEAR(end.input(0, 0), kSlideSpeed * kSlideSpeed / (2 * a * a), 1e-9);
  // Saltation of slip → stick: the velocity perturbation is absorbed (G_z row vx = 0).
  const ComposedGain gain = c.sensitivity().events()[0].gain_of_order({0});
  EXPECT_NEAR(gain.Gz.row(2).norm(), 0.0, 1e-12);
}

TEST(SlidingBlockSensitivity, PredictionErrorShrinksLikeEpsilonSquared) {
  sliding_block().expect_epsilon_squared("sliding_block", 21);
}

// --- incline: β = 20°, μ = 0.5, push u = c t down the slope ---------------------------------
constexpr double kSlope = 20.0 * M_PI / 180.0;
constexpr double kPushRate = 1.0;
constexpr double kInclineEnd = 2.0;

double slip_time() {
  return kGravity * (kFriction * std::cos(kSlope) - std::sin(kSlope)) / kPushRate;
}

FrictionCase incline() {
  return FrictionCase(
      {1.0, kGravity, kSlope, kFriction, 0.0}, {ContactPhase::kStick},
      Eigen::Vector4d(-0.5, 0.0, 0.0, 0.0),
      [](double t) { return Eigen::VectorXd::Constant(1, kPushRate * t); },
      [](double) { return Eigen::VectorXd::Constant(1, kPushRate); }, kInclineEnd);
}

TEST(InclineSensitivity, SlipsAtTheAnalyticTime) {
  const FrictionCase c = incline();
  ASSERT_EQ(c.nominal_run().events.size(), 1u);
  EXPECT_EQ(c.nominal_run().events[0].event.kind, GuardKind::kStickToSlip);
  EXPECT_EQ(c.nominal_run().events[0].event.phase_after, ContactPhase::kSlipPositive);
  EXPECT_NEAR(c.nominal_run().events[0].time, slip_time(), 1e-12);
  const double dt = kInclineEnd - slip_time();
  EXPECT_NEAR(c.nominal_run().final_state(0), -0.5 + kPushRate * dt * dt * dt / 6, 1e-10);
}

// The guard depends on the input: Δ = −(D_uγ v)/γ̇ with D_uγ = −1, γ̇ = −c, so a push
// perturbation v advances the slip by v/c (Δ = −v/c); the state is continuous across the
// switch (|λ_t| = μλ_n means the stick and slip fields agree), so G_z = I and G_v = 0.
TEST(InclineSensitivity, InputDependentGuardShiftsTheSlipTimeButNotTheState) {
  const FrictionCase c = incline();
  const ConewiseJumpGain& event = c.sensitivity().events()[0];
  const JumpGain& gain = event.micro_event({0}).gain;
  EXPECT_NEAR(gain.guard_rate, -kPushRate, 1e-10);
  EXPECT_NEAR(gain.b(0), -1.0 / kPushRate, 1e-10);
  EXPECT_NEAR(gain.a.norm(), 0.0, 1e-10);  // λ does not depend on the state here
  EXPECT_LT((gain.Gz - Eigen::MatrixXd::Identity(4, 4)).norm(), 1e-10);
  EXPECT_LT(gain.Gv.norm(), 1e-10);
  // First-order slip-time shift against a perturbed simulation with u + ε v0.
  const double eps = 1e-6, v0 = 0.7;
  const auto perturbed = test_utilities::simulate_reference(
      c.model(), {ContactPhase::kStick}, Eigen::Vector4d(-0.5, 0.0, 0.0, 0.0),
      [&](double t) { return Eigen::VectorXd::Constant(1, kPushRate * t + eps * v0); }, 0.0,
      kInclineEnd, {}, {5e-4, 50, {ContactPhase::kStick}});
  ASSERT_EQ(perturbed.events.size(), 1u);
  const double shift = (perturbed.events[0].time - c.nominal_run().events[0].time) / eps;
  EXPECT_NEAR(shift, gain.b(0) * v0, 1e-5);
}

// After the slip, ẍ = (c (t − t_s) + v(t))/m to first order (the perturbed slip time enters at
// second order because the net force vanishes at t_s), so z_x(T) = ∫_{t_s}^T (T − s) v(s) ds / m.
TEST(InclineSensitivity, EndPointInputMatrixMatchesTheClosedForm) {
  const FrictionCase c = incline();
  const InputBasis affine = [](double t) {
    Eigen::MatrixXd V(1, 2);
    V << 1.0, t;
    return V;
  };
  const EndPointSensitivity end = c.sensitivity().end_point_sensitivity(affine);
  const double ts = slip_time(), T = kInclineEnd, d = T - ts;
  EXPECT_NEAR(end.input(0, 0), d * d / 2, 1e-9);                       // ∫ (T − s) ds
  EXPECT_NEAR(end.input(0, 1), ts * d * d / 2 + d * d * d / 6, 1e-9);  // ∫ (T − s) s ds
  EXPECT_NEAR(end.input(2, 0), d, 1e-9);
  EXPECT_NEAR(end.state(0, 0), 1.0, 1e-12);
}

TEST(InclineSensitivity, PredictionErrorShrinksLikeEpsilonSquared) {
  incline().expect_epsilon_squared("incline", 33);
}

}  // namespace
}  // namespace impactbench::sensitivity
