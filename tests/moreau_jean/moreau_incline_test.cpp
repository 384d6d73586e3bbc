// Block on an incline of angle α under Moreau–Jean (box, Coulomb friction μ):
//  - tan α < μ: the block sticks, drift below 1e-9 m over 5 s;
//  - tan α > μ: it slides down with a = g (sin α − μ cos α) (the scheme is exact for constant
//    acceleration), to 1e-6 relative;
//  - pushed down the slope by u(t) = k t: slipping starts when k t + m g sin α = μ m g cos α;
//    the scheme evaluates the force at t_k + θh, so the first slipping step starts within one
//    step of that time.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "tests/support/lib/moreau_planar_worlds.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

constexpr double kGravity = 9.81;
constexpr double kSide = 0.2;
constexpr double kMass = 1.0;

Eigen::Vector2d normal(double alpha) {
  return {-std::sin(alpha), std::cos(alpha)};
}
Eigen::Vector2d tangent(double alpha) {
  return {std::cos(alpha), std::sin(alpha)};
}

// The box resting on the incline: centre at (side/2) n, turned by α.
Eigen::Vector3d resting_pose(double alpha) {
  const Eigen::Vector2d c = 0.5 * kSide * normal(alpha);
  return {c.x(), c.y(), alpha};
}

// `push`: one input, a force down the slope.
std::unique_ptr<model::LagrangianSystem<double>> incline(test_support::PlanarKind kind,
                                                         double alpha, double mu,
                                                         bool push = false) {
  test_support::PlanarWorldSpec spec;
  spec.bodies = {test_support::box("block", kSide, kSide, kMass)};
  spec.ground_angle = alpha;
  spec.gravity = kGravity;
  spec.material = {mu, 0.0};
  if (push) {
    const Eigen::Vector2d down = -tangent(alpha);
    spec.inputs.push_back({"block", Eigen::Vector3d(down.x(), down.y(), 0.0)});
  }
  return test_support::make_planar_world(kind, spec);
}

class MoreauIncline : public ::testing::TestWithParam<test_support::PlanarKind> {};

TEST_P(MoreauIncline, SticksBelowFrictionAngle) {
  const double alpha = 0.3, mu = 0.5;
  ASSERT_LT(std::tan(alpha), mu);
  const auto world = incline(GetParam(), alpha, mu);
  MoreauJeanOptions options;
  options.dt = 1e-3;
  options.record_impulses = false;
  MoreauJeanStepper stepper(*world, options);
  const Eigen::Vector3d q0 = resting_pose(alpha);
  const auto result = stepper.simulate(q0, Eigen::Vector3d::Zero(), {}, 5.0);
  ASSERT_TRUE(result.succeeded()) << result.message;
  const double drift = (result.final_state.q.head<2>() - q0.head<2>()).norm();
  std::printf("incline stick drift over 5 s: %.3e m\n", drift);
  EXPECT_LT(drift, 1e-9);
}

TEST_P(MoreauIncline, SlidesWithCoulombAcceleration) {
  const double alpha = 0.5, mu = 0.3;
  ASSERT_GT(std::tan(alpha), mu);
  const auto world = incline(GetParam(), alpha, mu);
  MoreauJeanOptions options;
  options.dt = 1e-3;
  options.record_impulses = false;
  MoreauJeanStepper stepper(*world, options);
  const double duration = 1.0;
  const auto result = stepper.simulate(resting_pose(alpha), Eigen::Vector3d::Zero(), {}, duration);
  ASSERT_TRUE(result.succeeded()) << result.message;
  const double speed_down = -tangent(alpha).dot(result.final_state.v.head<2>());
  const double expected = kGravity * (std::sin(alpha) - mu * std::cos(alpha));
  std::printf("incline slide acceleration %.12f expected %.12f\n", speed_down / duration, expected);
  EXPECT_NEAR(speed_down / duration, expected, 1e-6 * expected);
  EXPECT_NEAR(normal(alpha).dot(result.final_state.v.head<2>()), 0.0, 1e-9);
}

// First step at whose end the block moves, for a push k t down the slope.
double slip_start(test_support::PlanarKind kind, double dt, double alpha, double mu, double k,
                  double duration) {
  const auto world = incline(kind, alpha, mu, /*push=*/true);
  MoreauJeanOptions options;
  options.dt = dt;
  options.record_impulses = false;
  MoreauJeanStepper stepper(*world, options);
  double start = -1.0;
  double previous_t = 0.0;
  stepper.simulate(
      resting_pose(alpha), Eigen::Vector3d::Zero(),
      [k](double t) { return Eigen::VectorXd::Constant(1, k * t); }, duration,
      [&](const MoreauJeanState& s, const StepReport&) {
        if (start < 0 && s.v.head<2>().norm() > 1e-9) start = previous_t;
        previous_t = s.t;
      });
  return start;
}

TEST_P(MoreauIncline, PushedBlockStartsSlippingWithinOneStep) {
  const double alpha = 0.2, mu = 0.5, k = 2.0;
  const double t_star = kMass * kGravity * (mu * std::cos(alpha) - std::sin(alpha)) / k;
  for (double dt : {1e-2, 1e-3, 1e-4}) {
    const double start = slip_start(GetParam(), dt, alpha, mu, k, t_star + 0.05);
    ASSERT_GE(start, 0.0) << "never slipped, dt " << dt;
    std::printf("push: slip step starts at %.6f, analytical %.6f (dt %.0e)\n", start, t_star, dt);
    EXPECT_LE(std::abs(start - t_star), dt) << dt;
  }
}

INSTANTIATE_TEST_SUITE_P(Systems, MoreauIncline, test_support::all_planar_kinds(),
                         test_support::planar_kind_name);

}  // namespace
}  // namespace impactbench::engines::moreau_jean
