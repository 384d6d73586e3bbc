// A solid sphere (I = 2/5 m R²) launched on a plane with velocity v0 and spin ω0 (not aligned)
// under Moreau–Jean with the friction disk. The slip velocity of the contact point
// c = v + ω × (−R e_z) keeps its direction while friction −μ m g ĉ acts:
//   ċ = F/m + (R²/I) F = (7/2) F/m  ⇒  c reaches 0 at t* = 2‖c0‖/(7μg),
//   and then v = v0 − μ g ĉ t* = v0 − (2/7) c0 (rolling).
// The scheme decelerates c by 3.5 μ g h per step and sticks in the step that would overshoot:
// the slip→roll time is off by less than h.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

constexpr double kGravity = 9.81;
constexpr double kRadius = 0.1;
constexpr double kFriction = 0.3;

struct Rolling {
  double time = -1.0;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d final_velocity = Eigen::Vector3d::Zero();
  double final_spin_z = 0.0;
};

Eigen::Vector3d slip(const Eigen::VectorXd& v) {
  return v.head<3>() + v.tail<3>().cross(Eigen::Vector3d(0, 0, -kRadius));
}

Rolling spin(const Eigen::Vector3d& v0, const Eigen::Vector3d& w0, double dt,
             const std::string& solver = "nsgs") {
  const test_support::SphereOnPlaneTestSystem sphere(kRadius, 1.0, kGravity, kFriction, 0.0);
  MoreauJeanOptions options;
  options.dt = dt;
  options.solver = solver;
  options.record_impulses = false;
  MoreauJeanStepper stepper(sphere, options);
  Eigen::VectorXd q(7), v(6);
  q << 0, 0, kRadius, 1, 0, 0, 0;
  v << v0, w0;
  const double t_star = 2 * slip(v).norm() / (7 * kFriction * kGravity);
  Rolling rolling;
  const auto result =
      stepper.simulate(q, v, {}, 1.5 * t_star, [&](const MoreauJeanState& s, const StepReport&) {
        if (rolling.time < 0 && slip(s.v).norm() < 1e-8) {
          rolling.time = s.t;
          rolling.velocity = s.v.head<3>();
        }
      });
  EXPECT_TRUE(result.succeeded()) << result.message;
  rolling.final_velocity = result.final_state.v.head<3>();
  rolling.final_spin_z = result.final_state.v(5);
  return rolling;
}

const Eigen::Vector3d kV0(1.0, 0.0, 0.0);
const Eigen::Vector3d kW0(2.0, 5.0, 3.0);

TEST(MoreauSphereSpin, SlipToRollTimeAndRollingVelocity) {
  Eigen::VectorXd v(6);
  v << kV0, kW0;
  const Eigen::Vector3d c0 = slip(v);
  const double t_star = 2 * c0.norm() / (7 * kFriction * kGravity);
  const Eigen::Vector3d v_roll = kV0 - (2.0 / 7.0) * c0;
  for (double dt : {1e-3, 1e-4}) {
    const Rolling r = spin(kV0, kW0, dt);
    ASSERT_GT(r.time, 0.0) << "never rolled, dt " << dt;
    std::printf("sphere spin dt %.0e: t %.6f (t* %.6f), v (%.9f %.9f) expected (%.9f %.9f)\n", dt,
                r.time, t_star, r.velocity.x(), r.velocity.y(), v_roll.x(), v_roll.y());
    EXPECT_GE(r.time - t_star, -1e-12) << dt;
    EXPECT_LT(r.time - t_star, dt) << dt;
    // Exact, not only O(h): the contact impulse acts at the contact point P and gravity and the
    // normal impulse are vertical, so the scheme conserves the angular momentum about P,
    // I ω + R e_z × m v, step by step; rolling with it fixes v = v0 − (2/7) c0.
    EXPECT_LE((r.velocity - v_roll).norm(), 1e-9) << dt;
    EXPECT_LE((r.final_velocity - r.velocity).norm(), 1e-8) << "rolling must persist";
    EXPECT_NEAR(r.final_spin_z, kW0.z(), 1e-8) << "no torque about the normal";
  }
}

// The time error depends on where t* falls in a step: the worst over launch speeds that sweep
// that phase scales with h.
double worst_time_error(double dt) {
  double worst = 0.0;
  constexpr int kPhases = 16;
  for (int j = 0; j < kPhases; ++j) {
    const Eigen::Vector3d v0 =
        kV0 + Eigen::Vector3d(3.5 * kFriction * kGravity * dt * (j + 0.5) / kPhases, 0, 0);
    Eigen::VectorXd v(6);
    v << v0, kW0;
    const double t_star = 2 * slip(v).norm() / (7 * kFriction * kGravity);
    worst = std::max(worst, std::abs(spin(v0, kW0, dt).time - t_star));
  }
  return worst;
}

TEST(MoreauSphereSpin, SlipToRollTimeErrorIsFirstOrder) {
  const double coarse = worst_time_error(2e-3);
  const double fine = worst_time_error(1e-3);
  std::printf("sphere spin worst slip->roll time error: %.3e -> %.3e\n", coarse, fine);
  EXPECT_GE(coarse / fine, 1.6);
  EXPECT_LE(coarse / fine, 2.5);
}

// LCP solvers see the faceted cone (lcp_conversion.hpp): k generators d_j at angles 2πj/k in
// the tangent frame (here x̂, ŷ). While sliding, the impulse lies on the generator most opposed
// to the slip velocity, so its direction misses −c0 by the angle to the nearest generator,
// at most π/k. The disk law (nsgs) has no such error.
double angle_to_nearest_generator(const Eigen::Vector2d& direction, int k) {
  const double angle = std::atan2(direction.y(), direction.x());
  const double sector = 2 * std::numbers::pi / k;
  const double offset = angle - sector * std::round(angle / sector);
  return std::abs(offset);
}

struct FirstImpulse {
  Eigen::Vector2d tangential = Eigen::Vector2d::Zero();
  double roll_time = -1.0;
};

FirstImpulse faceted_run(const std::string& solver, int facets, double dt) {
  const test_support::SphereOnPlaneTestSystem sphere(kRadius, 1.0, kGravity, kFriction, 0.0);
  MoreauJeanOptions options;
  options.dt = dt;
  options.solver = solver;
  options.cone_facets = facets;
  MoreauJeanStepper stepper(sphere, options);
  Eigen::VectorXd q(7), v(6);
  q << 0, 0, kRadius, 1, 0, 0, 0;
  v << kV0, kW0;
  FirstImpulse first;
  const auto result =
      stepper.simulate(q, v, {}, 0.2, [&](const MoreauJeanState& s, const StepReport& report) {
        if (report.statistics.step_index == 1 && !report.impulses().empty())
          first.tangential = report.impulses()[0].r_t;
        if (first.roll_time < 0 && report.statistics.step_index > 0 && slip(s.v).norm() < 1e-8)
          first.roll_time = s.t;
      });
  EXPECT_TRUE(result.succeeded()) << result.message;
  return first;
}

TEST(MoreauSphereSpin, FacetedConeDirectionErrorIsAngleToNearestGenerator) {
  Eigen::VectorXd v(6);
  v << kV0, kW0;
  const Eigen::Vector2d minus_c0 = -slip(v).head<2>();
  const double t_star = 2 * minus_c0.norm() / (7 * kFriction * kGravity);
  const auto angle_between = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
  };
  const FirstImpulse disk = faceted_run("nsgs", 8, 1e-3);
  EXPECT_LT(angle_between(disk.tangential, minus_c0), 1e-6);
  // (pgs cannot solve the faceted LCP: its slack rows have a zero diagonal; lemke pivots.)
  for (const std::string solver : {"lemke"}) {
    for (int k : {4, 8, 16, 32}) {
      const FirstImpulse f = faceted_run(solver, k, 1e-3);
      const double error = angle_between(f.tangential, minus_c0);
      std::printf(
          "faceted cone %s k=%d: impulse direction error %.4f rad (%.2f deg, bound pi/k "
          "%.4f), slip->roll %.4f s vs disk %.4f s (t* %.4f)\n",
          solver.c_str(), k, error, error * 180 / std::numbers::pi, std::numbers::pi / k,
          f.roll_time, disk.roll_time, t_star);
      EXPECT_NEAR(error, angle_to_nearest_generator(minus_c0, k), 1e-6) << solver << " " << k;
      EXPECT_LE(error, std::numbers::pi / k + 1e-9);
    }
  }
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
