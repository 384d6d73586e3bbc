// Event-driven: a row of touching balls struck at one end is one simultaneous impact under
// Moreau's impact law, at t = 0 and later, checked against the law's closed form.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::engines::event_driven {
namespace {

// n equal balls of mass m on a line, ball 0 moving at v0 into ball 1, all neighbours touching
// (gap 0), Newton restitution e at every contact. Contact i (between balls i and i+1) has
// normal velocity ζ_i = v_{i+1} − v_i; before the impact ζ_0⁻ = −v0, ζ_i⁻ = 0 for i ≥ 1.
// Moreau's law: 0 ≤ P_i ⊥ ζ_i⁺ + e min(ζ_i⁻, 0) ≥ 0, with m (v_i⁺ − v_i⁻) = P_{i−1} − P_i.
// Guess every contact active: ζ_0⁺ = e v0 and ζ_i⁺ = 0 (i ≥ 1), so balls 1 … n−1 share one
// velocity w and ball 0 has w − e v0; momentum n w − e v0 = v0 gives w = (1 + e) v0 / n.
// The impulses are positive: ball n−1 gives P_{n−2} = m w, ball i (1 ≤ i ≤ n−2) gives
// P_{i−1} − P_i = m w, so P_i = (n − 1 − i) m w > 0, and P_0 = m (v0 − v_0⁺) > 0. The Delassus
// matrix of the chain (tridiagonal, 2/m on the diagonal, −1/m beside it) is positive definite,
// so this solution of the complementarity problem is the only one:
//     v_0⁺ = ((1 + e)/n − e) v0,   v_i⁺ = (1 + e) v0 / n  (i ≥ 1).
// (n = 3, e = 1: (−1/3, 2/3, 2/3); n = 5: (−3/5, 2/5, 2/5, 2/5, 2/5).) No impact follows: ball 0
// recedes and the others move together.
double moreau_velocity(int ball, int n, double e, double v0) {
  const double shared = (1 + e) * v0 / n;
  return ball == 0 ? shared - e * v0 : shared;
}

struct CradleCase {
  int count;
  double restitution;
  double gap0;  // gap between ball 0 and ball 1 (the rest touch): 0 strikes at t = 0
};

class EventTouchingCradle : public ::testing::TestWithParam<CradleCase> {};

TEST_P(EventTouchingCradle, IsOneSimultaneousImpactOfMoreausLaw) {
  const CradleCase c = GetParam();
  const double v0 = 1.0;
  const scenario::Scenario s = scenario::load_scenario_by_name(
      "newtons_cradle",
      {{"count", c.count}, {"gap", 0.0}, {"restitution", c.restitution}, {"v0", v0}});
  engines::BuiltSystem built = engines::build_system(s);
  // Ball 0 starts gap0 further back: the impact happens at t = gap0 / v0 instead of t = 0.
  built.q0(0) -= c.gap0;
  EventDrivenOptions options;
  options.output_interval = 0.0;
  EventDrivenIntegrator integrator(*built.system, options);
  const double duration = c.gap0 / v0 + 0.05;
  const EventDrivenResult result = integrator.simulate(built.q0, built.v0, {}, duration);
  ASSERT_TRUE(result.succeeded()) << result.message;
  const int nv_per_body = static_cast<int>(built.v0.size()) / c.count;
  for (int i = 0; i < c.count; ++i)
    EXPECT_NEAR(result.v(nv_per_body * i), moreau_velocity(i, c.count, c.restitution, v0), 1e-9)
        << "ball " << i << " of " << c.count << ", e = " << c.restitution
        << ", impact at t = " << c.gap0 / v0;
}

std::string case_name(const ::testing::TestParamInfo<CradleCase>& info) {
  std::string name = "n";
  name.append(std::to_string(info.param.count))
      .append("_e")
      .append(std::to_string(static_cast<int>(std::lround(info.param.restitution * 10))))
      .append(info.param.gap0 > 0 ? "_later" : "_at_start");
  return name;
}

INSTANTIATE_TEST_SUITE_P(Rows, EventTouchingCradle,
                         ::testing::Values(CradleCase{2, 1.0, 0.0}, CradleCase{3, 1.0, 0.0},
                                           CradleCase{4, 1.0, 0.0}, CradleCase{5, 1.0, 0.0},
                                           CradleCase{6, 1.0, 0.0}, CradleCase{3, 0.5, 0.0},
                                           CradleCase{5, 0.5, 0.0}, CradleCase{3, 1.0, 0.01},
                                           CradleCase{5, 0.5, 0.01}, CradleCase{6, 1.0, 0.01}),
                         case_name);

}  // namespace
}  // namespace impactbench::engines::event_driven
