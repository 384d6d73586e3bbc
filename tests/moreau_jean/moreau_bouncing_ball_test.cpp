// Bouncing ball under Moreau–Jean: apex heights after each bounce against the analytical
// r + (h0 − r) e^(2k), and first-order convergence of their error in h.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "tests/support/lib/moreau_planar_worlds.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

constexpr double kGravity = 9.81;
constexpr double kRadius = 0.1;
constexpr double kRestitution = 0.9;
constexpr int kBounces = 5;

std::unique_ptr<model::LagrangianSystem<double>> ball_world(test_support::PlanarKind kind) {
  test_support::PlanarWorldSpec spec;
  spec.bodies = {test_support::disk("ball", kRadius, 1.0)};
  spec.gravity = kGravity;
  spec.material = {0.0, kRestitution};
  return test_support::make_planar_world(kind, spec);
}

// Apex height of the centre after each of the first kBounces bounces (max over the nodes
// between two impacts).
std::vector<double> apex_heights(test_support::PlanarKind kind, double h0, double dt) {
  const auto world = ball_world(kind);
  MoreauJeanOptions options;
  options.dt = dt;
  options.record_impulses = false;
  MoreauJeanStepper stepper(*world, options);
  std::vector<double> apexes;
  bool after_bounce = false;
  const double fall = std::sqrt(2 * (h0 - kRadius) / kGravity);
  double flight_sum = fall;
  for (int k = 1; k <= kBounces; ++k) flight_sum += 2 * fall * std::pow(kRestitution, k);
  stepper.simulate(Eigen::Vector3d(0, h0, 0), Eigen::Vector3d::Zero(), {}, flight_sum,
                   [&](const MoreauJeanState& s, const StepReport& report) {
                     const bool impact =
                         std::any_of(report.impulses().begin(), report.impulses().end(),
                                     [](const ContactImpulse& c) { return c.r_n > 0.0; });
                     if (impact) {
                       if (static_cast<int>(apexes.size()) == kBounces) return;
                       apexes.push_back(s.q(1));
                       after_bounce = true;
                     } else if (after_bounce && !apexes.empty()) {
                       apexes.back() = std::max(apexes.back(), s.q(1));
                     }
                   });
  return apexes;
}

double analytical_apex(double h0, int k) {
  return kRadius + (h0 - kRadius) * std::pow(kRestitution, 2 * k);
}

// First-order error bound. With the default activation γ = θ = 1/2 the impact step starts
// at a gap g_k = (γ − 1 + s) h V, s ∈ (0, 1] (active: g_k ≤ γ h V; the step before was not:
// g_k > (γ − 1) h V). It leaves at g_k − h V (1 − e)/2 with speed e V; the exact apex is
// e² V_c²/(2g) with V_c² = V² + 2 g g_k the speed at the surface, so the apex errs by
// g_k (1 − e²) − h V (1 − e)/2 = h V ((γ − 1 + s)(1 − e²) − (1 − e)/2), largest at s = 0 or 1,
// and an apex error δ propagates as e² δ.
std::vector<double> error_bounds(double h0, double dt) {
  std::vector<double> bounds;
  double previous = 0.0;
  for (int k = 1; k <= kBounces; ++k) {
    const double speed = std::sqrt(2 * kGravity * (analytical_apex(h0, k - 1) - kRadius));
    constexpr double kGamma = 0.5;
    const double e2 = kRestitution * kRestitution;
    const double local = dt * speed *
                         std::max(std::abs(kGamma * (1 - e2) - (1 - kRestitution) / 2),
                                  std::abs((kGamma - 1) * (1 - e2) - (1 - kRestitution) / 2));
    previous = local + kRestitution * kRestitution * previous;
    bounds.push_back(previous);
  }
  return bounds;
}

class MoreauBouncingBall : public ::testing::TestWithParam<test_support::PlanarKind> {};

TEST_P(MoreauBouncingBall, ApexHeightsWithinFirstOrderBound) {
  for (double dt : {2e-3, 1e-3, 5e-4}) {
    const double h0 = 1.0;
    const auto apexes = apex_heights(GetParam(), h0, dt);
    ASSERT_EQ(apexes.size(), static_cast<std::size_t>(kBounces));
    const auto bounds = error_bounds(h0, dt);
    for (int k = 1; k <= kBounces; ++k) {
      // Slack for the O(h²) terms of the derivation (node sampling of the apex: g h²/8 each).
      EXPECT_LE(std::abs(apexes[k - 1] - analytical_apex(h0, k)),
                bounds[k - 1] + k * kGravity * dt * dt)
          << "dt " << dt << " bounce " << k;
    }
  }
}

// The error of one bounce depends on where the impact falls within a step (s above), so what
// scales with h is the worst error over initial heights that sweep that phase. Each bounce is
// compared with the analytical map apex_k = r + e² (apex_{k−1} − r) applied to the computed
// previous apex: accumulated errors with pseudo-random phases would blur the ratio.
double worst_bounce_error(test_support::PlanarKind kind, double dt) {
  const double h0 = 1.0;
  const double speed = std::sqrt(2 * kGravity * (h0 - kRadius));
  double worst = 0.0;
  constexpr int kPhases = 16;
  for (int j = 0; j < kPhases; ++j) {
    const double height = h0 + speed * dt * j / kPhases;  // first impact swept over one step
    const auto apexes = apex_heights(kind, height, dt);
    EXPECT_EQ(apexes.size(), static_cast<std::size_t>(kBounces));
    double previous = height;
    for (double apex : apexes) {
      const double expected = kRadius + kRestitution * kRestitution * (previous - kRadius);
      worst = std::max(worst, std::abs(apex - expected));
      previous = apex;
    }
  }
  return worst;
}

TEST_P(MoreauBouncingBall, ApexErrorIsFirstOrder) {
  const double coarse = worst_bounce_error(GetParam(), 2e-3);
  const double medium = worst_bounce_error(GetParam(), 1e-3);
  const double fine = worst_bounce_error(GetParam(), 5e-4);
  std::printf("bouncing ball worst apex error: %.3e %.3e %.3e\n", coarse, medium, fine);
  EXPECT_GE(coarse / medium, 1.6);
  EXPECT_LE(coarse / medium, 2.5);
  EXPECT_GE(medium / fine, 1.6);
  EXPECT_LE(medium / fine, 2.5);
}

INSTANTIATE_TEST_SUITE_P(Systems, MoreauBouncingBall, test_support::all_planar_kinds(),
                         test_support::planar_kind_name);

}  // namespace
}  // namespace impactbench::engines::moreau_jean
