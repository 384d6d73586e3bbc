// No step size lets Moreau–Jean miss an impact: the bouncing ball at coarse steps and a sphere
// pile at h = 1e-2 stay within penetration bounds derived from the scheme (below), and no
// contact is ever found already penetrated without the search having seen it coming.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

struct LoadedRun {
  scenario::Scenario scenario;
  engines::BuiltSystem built;
};

LoadedRun load(const std::string& name, const scenario::ParameterOverrides& overrides) {
  LoadedRun run{scenario::load_scenario_by_name(name, overrides), {}};
  run.built = engines::build_system(run.scenario);
  return run;
}

// Bouncing ball (gap g = y − r, normal velocity ζ = ẏ, gravity a), θ = 1/2, activation rule
// g_k + γ h ζ_k ≤ τ with τ ≥ 0. Without impulse a step gives ζ_{k+1} = ζ_k − a h and
// g_{k+1} = g_k + h (ζ_k + ζ_{k+1})/2 = g_k + h ζ_k − a h²/2.
//  (A) An inactive step has g_k > −γ h ζ_k, so g_{k+1} > (1 − γ) h ζ_k − a h²/2
//      ≥ −((1 − γ) h |ζ_k| + a h²/2).
//  (B) An active step with ζ_k < 0 gives ζ_{k+1} = max(ζ_k − a h, −e ζ_k) = e |ζ_k| (Newton's
//      law at velocity level), so g drops once more, by h (1 − e) |ζ_k| / 2, and ζ_{k+1} ≥ 0.
//      An active step with ζ_k ≥ 0 ends with ζ_{k+1} = max(ζ_k − a h, 0) ≥ 0: g does not drop.
// Two active steps in a row cannot both start with ζ < 0 (the first ends with ζ ≥ 0), so an
// impact step follows an inactive step, whose start speed V_pre raises |ζ| by a h at most:
//      penetration ≤ (1 − γ) h V + a h²/2 + (1 − e) h (V + a h)/2.
// V: free flight is exact at the nodes for constant gravity with θ = 1/2 (½ ζ² + a g is kept),
// impact steps lose energy (½ (e² − 1) ζ² − (1 − e) a h |ζ|/2 ≤ 0), and a step that stops a
// rising ball with ζ < a h gains at most a² h²/8 and leaves it at rest; hence
// V ≤ √(2 a (y0 − r) + a² h²/4) ≤ √(2 a (y0 − r)) + a h.
double ball_penetration_bound(double a, double y0, double r, double e, double h, double gamma) {
  const double speed = std::sqrt(2 * a * (y0 - r)) + a * h;
  return (1 - gamma) * h * speed + a * h * h / 2 + (1 - e) * h * (speed + a * h) / 2;
}

class MoreauMissedImpact : public ::testing::TestWithParam<double> {};

TEST_P(MoreauMissedImpact, BouncingBallStaysWithinTheDerivedPenetration) {
  const double h = GetParam();
  const LoadedRun run = load("bouncing_ball", {{"height", 2.0}});
  const scenario::Scenario& s = run.scenario;
  MoreauJeanOptions options;  // default activation: γ = θ = 1/2
  options.dt = h;
  options.record_impulses = false;
  const double gamma = 0.5;
  double lowest = 1e300;
  MoreauJeanStepper stepper(*run.built.system, options);
  const SimulationResult result =
      stepper.simulate(run.built.q0, run.built.v0, {}, s.duration,
                       [&](const MoreauJeanState& state, const StepReport&) {
                         lowest = std::min(lowest, state.q(1));
                       });
  ASSERT_TRUE(result.succeeded()) << result.message;
  const double r = s.parameter("radius");
  const double bound = ball_penetration_bound(s.parameter("g"), s.parameter("height"), r,
                                              s.parameter("restitution"), h, gamma);
  EXPECT_LE(r - lowest, bound) << "h = " << h;
  EXPECT_LE(result.summary.max_penetration, bound) << "h = " << h;
  EXPECT_EQ(result.summary.late_contacts, 0) << "h = " << h;
}

INSTANTIATE_TEST_SUITE_P(CoarseSteps, MoreauMissedImpact, ::testing::Values(2e-3, 5e-3, 1e-2));

// Sphere pile, θ = γ = 1/2. A contact entering the active set at step k (inactive at step
// k − 1, so g_{k−1} > −h ζ_{k−1}/2 with ζ measured along the normal n_{k−1} at q_{k−1}) has a
// gap that is convex in the centres (|x_a − x_b| − r_a − r_b, or linear for a wall), so
// g_k ≥ g_{k−1} + n_{k−1}·(x_k − x_{k−1}) = g_{k−1} + h (ζ_{k−1} + n_{k−1}·Δv_k)/2 > h
// n_{k−1}·Δv_k/2, with Δv_k the centres' relative velocity at t_k (the θ-blend of the positions
// uses v_{k−1} and v_k). Hence its penetration when it enters is at most h |Δv_k| / 2, whatever
// pushed it. A contact the search missed enters already penetrated by up to h |ζ| and breaks this.
TEST(MoreauMissedImpactPile, ContactsEnterWithinHalfAStepOfApproach) {
  constexpr double h = 1e-2;
  // 64 spheres in four layers: the last lands about 0.5 s after release; 1.2 s covers the
  // landings and the first rebounds (a test-sized pile).
  const LoadedRun run = load("sphere_pile", {{"count", 64.0}});
  constexpr double kDuration = 1.2;
  MoreauJeanOptions options;
  options.dt = h;
  options.tolerance = 1e-8;
  options.on_failure = OnFailure::kWarn;
  options.record_impulses = false;
  MoreauJeanStepper stepper(*run.built.system, options);
  Eigen::VectorXd v_previous = run.built.v0;
  std::set<model::ContactKey> active_before;
  int entering = 0;
  double worst_excess = -1e300;
  std::string worst;
  const auto linear_velocity = [](const Eigen::VectorXd& v, int body) -> Eigen::Vector3d {
    return body < 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(v.segment<3>(6 * body));
  };
  const SimulationResult result =
      stepper.simulate(run.built.q0, run.built.v0, {}, kDuration,
                       [&](const MoreauJeanState& s, const StepReport& report) {
                         std::set<model::ContactKey> active_now;
                         for (const ContactImpulse& c : report.impulses()) {
                           active_now.insert(c.key);
                           if (active_before.count(c.key)) continue;
                           ++entering;
                           const double bound = h / 2 *
                                                (linear_velocity(v_previous, c.key.body_a) -
                                                 linear_velocity(v_previous, c.key.body_b))
                                                    .norm();
                           if (-c.gap - bound > worst_excess) {
                             worst_excess = -c.gap - bound;
                             worst = c.name + " at t = " + std::to_string(s.t);
                           }
                         }
                         active_before = std::move(active_now);
                         v_previous = s.v;
                       });
  ASSERT_TRUE(result.succeeded()) << result.message;
  std::printf("sphere pile: %d contacts entered, worst excess over h |Δv|/2: %.3g m\n", entering,
              worst_excess);
  EXPECT_GT(entering, 64);  // the pile forms: every sphere lands, many touch each other
  EXPECT_LE(worst_excess, 1e-12) << worst;
  EXPECT_EQ(result.summary.late_contacts, 0);
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
