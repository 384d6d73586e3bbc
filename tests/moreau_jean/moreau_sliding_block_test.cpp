// Sliding block under Moreau–Jean: a box launched at v0 on flat ground with Coulomb friction μ
// stops at t* = v0/(μg) after d* = v0²/(2μg). The scheme decelerates exactly by μgh per step
// and sticks in the step where |v| < μgh, so
//   stop time:  t_num − t* ∈ [0, h)                       (first order),
//   distance:   d_num − d* = v_k/2 (h − v_k/(μg)) ∈ [0, μgh²/8]  (second order, θ = 1/2).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "tests/support/lib/moreau_planar_worlds.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

constexpr double kGravity = 9.81;
constexpr double kFriction = 0.5;
constexpr double kSide = 0.2;

struct Stop {
  double time = -1.0;
  double distance = 0.0;
  double max_abs_rotation = 0.0;
};

Stop slide(test_support::PlanarKind kind, double v0, double dt) {
  test_support::PlanarWorldSpec spec;
  spec.bodies = {test_support::box("block", kSide, kSide, 1.0)};
  spec.gravity = kGravity;
  spec.material = {kFriction, 0.0};
  const auto world = test_support::make_planar_world(kind, spec);
  MoreauJeanOptions options;
  options.dt = dt;
  options.record_impulses = false;
  MoreauJeanStepper stepper(*world, options);
  Stop stop;
  const double duration = 1.5 * v0 / (kFriction * kGravity);
  const auto result =
      stepper.simulate(Eigen::Vector3d(0, kSide / 2, 0), Eigen::Vector3d(v0, 0, 0), {}, duration,
                       [&](const MoreauJeanState& s, const StepReport&) {
                         stop.max_abs_rotation = std::max(stop.max_abs_rotation, std::abs(s.q(2)));
                         if (stop.time < 0 && std::abs(s.v(0)) < 1e-9) {
                           stop.time = s.t;
                           stop.distance = s.q(0);
                         }
                       });
  EXPECT_TRUE(result.succeeded()) << result.message;
  return stop;
}

class MoreauSlidingBlock : public ::testing::TestWithParam<test_support::PlanarKind> {};

TEST_P(MoreauSlidingBlock, StopTimeWithinOneStepAndDistanceSecondOrder) {
  const double v0 = 2.0;
  const double t_star = v0 / (kFriction * kGravity);
  const double d_star = v0 * v0 / (2 * kFriction * kGravity);
  for (double dt : {1e-2, 1e-3}) {
    const Stop stop = slide(GetParam(), v0, dt);
    EXPECT_GE(stop.time - t_star, -1e-12) << dt;
    EXPECT_LT(stop.time - t_star, dt) << dt;
    EXPECT_GE(stop.distance - d_star, -1e-12) << dt;
    EXPECT_LE(stop.distance - d_star, kFriction * kGravity * dt * dt / 8 + 1e-12) << dt;
    // Not tipping (μ = 0.5 < width/height): the rotation stays at the level the solver tolerance
    // (1e-10 relative per step, some hundred steps) allows.
    EXPECT_LT(stop.max_abs_rotation, 1e-8) << "the square block must not tip at μ = 0.5";
  }
}

// Errors depend on where t* falls within a step; the worst error over speeds that sweep that
// phase is what scales with h (time: h, distance: h²).
struct WorstErrors {
  double time = 0.0;
  double distance = 0.0;
};

WorstErrors worst_errors(test_support::PlanarKind kind, double dt) {
  WorstErrors worst;
  constexpr int kPhases = 16;
  for (int j = 0; j < kPhases; ++j) {
    const double v0 = 2.0 + kFriction * kGravity * dt * (j + 0.5) / kPhases;
    const Stop stop = slide(kind, v0, dt);
    worst.time = std::max(worst.time, std::abs(stop.time - v0 / (kFriction * kGravity)));
    worst.distance =
        std::max(worst.distance, std::abs(stop.distance - v0 * v0 / (2 * kFriction * kGravity)));
  }
  return worst;
}

TEST_P(MoreauSlidingBlock, ConvergenceOrders) {
  const WorstErrors coarse = worst_errors(GetParam(), 2e-3);
  const WorstErrors fine = worst_errors(GetParam(), 1e-3);
  std::printf("sliding block worst errors: time %.3e -> %.3e, distance %.3e -> %.3e\n", coarse.time,
              fine.time, coarse.distance, fine.distance);
  EXPECT_GE(coarse.time / fine.time, 1.6);
  EXPECT_LE(coarse.time / fine.time, 2.5);
  EXPECT_GE(coarse.distance / fine.distance, 3.2);
  EXPECT_LE(coarse.distance / fine.distance, 5.0);
}

INSTANTIATE_TEST_SUITE_P(Systems, MoreauSlidingBlock, test_support::all_planar_kinds(),
                         test_support::planar_kind_name);

}  // namespace
}  // namespace impactbench::engines::moreau_jean
