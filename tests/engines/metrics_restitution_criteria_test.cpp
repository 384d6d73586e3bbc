// The contact-law criteria hold on the velocity-level law with Newton's restitution,
// ζ_n = ζ_n⁺ + e min(ζ_n⁻, 0): an exact impact scores 0 at any e, where λ_n ζ_n⁺ alone (the
// criterion before) counted every rebound as a violation of m (1 + e) v · e v.
#include <cmath>

#include <gtest/gtest.h>

#include "lib/metrics/contact_criteria.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::metrics {
namespace {

// A ball of mass m hitting the ground at v = 3 m/s, restituted exactly: ζ_n⁻ = −v,
// ζ_n⁺ = e v, λ_n = m (1 + e) v.
engines::ContactSample exact_impact(double e) {
  constexpr double kMass = 2.0, kSpeed = 3.0;
  engines::ContactSample c;
  c.friction = 0.4;
  c.restitution = e;
  c.velocity_n_before = -kSpeed;
  c.velocity_n = e * kSpeed;
  c.impulse_n = kMass * (1.0 + e) * kSpeed;
  return c;
}

class ExactImpact : public ::testing::TestWithParam<double> {};

TEST_P(ExactImpact, ScoresZero) {
  const ContactCriteria k = contact_criteria(exact_impact(GetParam()), 1e-9);
  EXPECT_EQ(k.signorini, 0.0);
  EXPECT_EQ(k.complementarity, 0.0);
  EXPECT_EQ(k.friction_cone, 0.0);
  EXPECT_EQ(k.max_dissipation, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Restitution, ExactImpact, ::testing::Values(0.0, 0.5, 0.9));

TEST(RestitutionCriteria, AReboundBelowNewtonsLawIsMeasured) {
  // e = 0.5, but the ball leaves at 1 m/s instead of 1.5: ζ_n = 1 − 1.5 = −0.5 m/s while the
  // impulse is 2 (1.5)(3) = 9 N·s, |λ_n ζ_n| = 4.5 N·m.
  engines::ContactSample c = exact_impact(0.5);
  c.velocity_n = 1.0;
  EXPECT_NEAR(contact_criteria(c, 1e-9).signorini, 4.5, 1e-12);
}

TEST(RestitutionCriteria, NoRestitutionOnAContactThatWasSeparating) {
  // Separating at the step's start (ζ_n⁻ > 0): Newton's law adds nothing, ζ_n = ζ_n⁺.
  engines::ContactSample c = exact_impact(0.9);
  c.velocity_n_before = 0.2;
  c.velocity_n = 0.1;
  c.impulse_n = 1.0;
  EXPECT_NEAR(restituted_normal_velocity(c), 0.1, 1e-15);
  EXPECT_NEAR(contact_criteria(c, 1e-9).signorini, 0.1, 1e-15);
}

// Moreau–Jean solves exactly this law: on one impact of the bouncing ball at each e, the
// criteria are at the solver's tolerance, not at m (1 + e) v · e v.
class MoreauSingleImpact : public ::testing::TestWithParam<double> {};

TEST_P(MoreauSingleImpact, ScoresZeroWhereTheOldCriterionDidNot) {
  const double e = GetParam();
  const auto s = scenario::load_scenario_by_name("bouncing_ball", {{"restitution", e}});
  engines::SettingsRequest request;
  request.duration = 0.6;  // the first impact at t = √(2 · 0.9 / 9.81) = 0.43 s, one only
  const auto run =
      adapters::run_engine("moreau", s, engines::resolve_run_options("moreau", s, request));
  const ContactCriteria k = worst_contact_criteria(run.steps);
  double old_signorini = 0.0, impulse = 0.0;
  for (const auto& step : run.steps)
    for (const auto& c : step.contacts) {
      old_signorini = std::max(old_signorini, std::abs(c.impulse_n * c.velocity_n));
      impulse = std::max(impulse, c.impulse_n);
    }
  ASSERT_GT(impulse, 4.0);  // the impact was in the run: m v = √(2 g 0.9) = 4.2 N·s at least
  // The law is solved to the scenario's tolerance 1e-10 on velocities; λ_n ≤ 8 N·s.
  EXPECT_LT(k.signorini, 1e-8);
  EXPECT_LT(k.complementarity, 1e-8);
  // λ_n ζ_n⁺ = m (1 + e) v · e v = (1 + e) e · 2 g 0.9: 0 at e = 0, 13.2 at 0.5, 30.2 at 0.9.
  // Moreau–Jean's impact speed is v up to one step of gravity (g h = 0.01 m/s, 1 % of 2 g h v).
  const double closed_form = (1.0 + e) * e * 2.0 * 9.81 * 0.9;
  EXPECT_NEAR(old_signorini, closed_form, 0.01 * closed_form + 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Restitution, MoreauSingleImpact, ::testing::Values(0.0, 0.5, 0.9));

}  // namespace
}  // namespace impactbench::metrics
