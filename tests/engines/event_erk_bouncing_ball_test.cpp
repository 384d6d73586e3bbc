// The event-driven engine with `method = erk` (ARKODE's Dormand–Prince pair) and `own_erk` (our
// own driver of the same pair) on the bouncing ball: each of the first impacts and apexes against
// the closed form, to a bound derived from the root search's tolerance alone (a flight under
// gravity is integrated and interpolated exactly by the pair and its cubic Hermite output, up to
// round-off).
#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/erk_table.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/compare/analytic_errors.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

engines::RunResult run_with(const scenario::Scenario& s, const std::string& method) {
  engines::SettingsRequest request;
  request.options = {{"method", method}};
  return adapters::run_engine("event", s, engines::resolve_run_options("event", s, request));
}

std::vector<double> impact_event_times(const engines::RunResult& run) {
  std::vector<double> times;
  for (const auto& event : run.events)
    if (event.kind == "impact") times.push_back(event.t);
  return times;
}

// Bounds on the errors of impacts 0..n−1 and of apexes 1..n (closed form: impact k at T_k with
// speed v_k = e^k v₁, the flight after it 2 e v_k / g long).
//  - The root search returns the upper end of a bracket of width τ_k = 100 ε (|t| + |h|)
//    (CVODE's and ARKODE's tolerance), so impact k is located δ_k ∈ [0, τ_k] after the crossing
//    of the computed trajectory; with the step h ≤ t (no step starts before 0), τ_k ≤ 200 ε T_k.
//    Round-off of erk's interpolated state (a few ε of the height scale, H = the release height)
//    adds 8 ε H / v_k.
//    own_erk evaluates its dense output nested (own_erk_session.cpp),
//    y₀ + θ (Δ + (1 − θ) (r₂ + θ (r₃ + (1 − θ) E))), with |Δ| ≤ h m, |r₂| ≤ 2 h m, |r₃| ≤ 4 h m
//    (m the largest |k_i|: a speed ≤ v₁ in the height, g in the speed) and E = h Σ e_i k_i zero
//    on a flight. Rounding: 3 operations for r₂ and r₃ (21 ε h m), 8 in the nesting and 4 in θ
//    and 1 − θ on partial sums ≤ 7 h m (84 ε h m), ε |y₀|, and E's 7 products summed
//    (9 ε h ‖e‖₁ m, times θ² (1 − θ)² ≤ 1/16); h ≤ 2 v₁ / g (no step is longer than the longest
//    flight). A height error δH = ε H + (105 + 9 ‖e‖₁ / 16) ε h v₁ (δH / v_k in time and in
//    every apex sample) and a speed error δV = ε v₁ + (105 + 9 ‖e‖₁ / 16) ε h g (that of a time
//    offset δV / g).
struct Bounds {
  std::vector<double> impact, apex;
};

// The round-off of the interpolated height and speed (above).
struct DenseRoundOff {
  double height = 0.0, speed = 0.0;
};

DenseRoundOff dense_round_off(const scenario::Scenario& s, const std::string& method) {
  const double v1 = s.analytic("v_first"), height = s.parameter("height"), g = s.parameter("g");
  if (method != "own_erk") return {8.0 * DBL_EPSILON * height, 0.0};
  using engines::event_driven::ErkPair;
  const auto pair = engines::event_driven::load_butcher_pair(ErkPair::kDormandPrince54);
  const double roundings = 105.0 + 9.0 * pair.quartic_correction.lpNorm<1>() / 16.0;
  const double h_max = 2.0 * v1 / g;
  return {DBL_EPSILON * height + roundings * DBL_EPSILON * h_max * v1,
          DBL_EPSILON * v1 + roundings * DBL_EPSILON * h_max * g};
}

Bounds derived_bounds(const scenario::Scenario& s, int n, const DenseRoundOff& dense) {
  const double e = s.parameter("restitution"), v1 = s.analytic("v_first");
  const double g = s.parameter("g");
  std::vector<double> tau;
  for (int k = 0; k < n; ++k) {
    const double v_k = v1 * std::pow(e, k);
    tau.push_back(200.0 * DBL_EPSILON * s.analytic("impact_time", k) + dense.height / v_k +
                  dense.speed / g);
  }
  Bounds b;
  for (int k = 0; k < n; ++k) {
    double impact = tau[static_cast<std::size_t>(k)], apex = 0.0;
    for (int j = 0; j < k; ++j) {
      double later_flights = 0.0;
      for (int m = 1; m < k - j; ++m) later_flights += 2.0 * std::pow(e, m);
      impact += (1.0 + 2.0 * e + 1.0 / e + later_flights) * tau[static_cast<std::size_t>(j)];
    }
    for (int j = 0; j <= k; ++j) apex += (e * e + 1.0 + e) * v1 * tau[static_cast<std::size_t>(j)];
    b.impact.push_back(impact);
    b.apex.push_back(apex + dense.height);
  }
  return b;
}

class EventErkBouncingBall : public testing::TestWithParam<std::string> {};

TEST_P(EventErkBouncingBall, ImpactTimesAndApexesMatchTheClosedFormToTheRootTolerance) {
  const scenario::Scenario s = scenario::load_scenario_by_name("bouncing_ball");
  const engines::RunResult run = run_with(s, GetParam());
  const int n = compare::kCheckedBounces;
  const Bounds bounds = derived_bounds(s, n, dense_round_off(s, GetParam()));
  const std::vector<double> impacts = impact_event_times(run);
  ASSERT_GE(static_cast<int>(impacts.size()), n);
  for (int k = 0; k < n; ++k) {
    const double error = impacts[static_cast<std::size_t>(k)] - s.analytic("impact_time", k);
    EXPECT_LE(std::abs(error), bounds.impact[static_cast<std::size_t>(k)]) << "impact " << k;
    // The requirement the method was chosen by: within 1e-12 s at the default tolerance.
    EXPECT_LE(std::abs(error), 1e-12) << "impact " << k;
  }
  // The apexes as compare measures them (a parabola through the samples around each top, exact
  // for a parabola): the largest error over apexes 1..n.
  const double apex_error = compare::named_value(compare::analytic_errors(s, run), "apex_error");
  EXPECT_LE(std::abs(apex_error), bounds.apex.back());
  EXPECT_LE(std::abs(apex_error), 1e-12);
}

TEST_P(EventErkBouncingBall, TakesFewerStepsThanCvodeForTheSameImpacts) {
  // A flight under constant forces is exact for the pair: once the guard is armed the step
  // carried over the impact covers the flight, where CVODE restarts at order 1 every bounce.
  const scenario::Scenario s = scenario::load_scenario_by_name("bouncing_ball");
  const engines::RunResult erk = run_with(s, GetParam());
  engines::SettingsRequest adams;
  adams.options = {{"method", "adams"}};
  const engines::RunResult cvode =
      adapters::run_engine("event", s, engines::resolve_run_options("event", s, adams));
  ASSERT_EQ(impact_event_times(erk).size(), impact_event_times(cvode).size());
  const auto steps = [](const engines::RunResult& r) {
    for (const auto& [name, value] : r.summary)
      if (name == "integrator steps (method)") return std::stod(value);
    return 0.0;
  };
  EXPECT_GT(steps(erk), 0.0);
  EXPECT_LT(steps(erk), steps(cvode) / 2);
}

INSTANTIATE_TEST_SUITE_P(Methods, EventErkBouncingBall, testing::Values("erk", "own_erk"));

}  // namespace
}  // namespace impactbench
