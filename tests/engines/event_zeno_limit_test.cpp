// Event-driven: the accumulation point t∞ of a bouncing ball's impacts is reported (a
// zeno_limit event, the run summary, compare's accumulation_time_error) and agrees with the
// closed form.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "lib/scenario/scenario.hpp"
#include "tests/support/engines/scenario_runs.hpp"
#include "tools/compare/analytic_errors.hpp"
#include "tools/engines/event/event_engine.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::engines::event_driven {
namespace {

// A ball released at rest with its centre at y0 reaches the ground after t1 = √(2 (y0 − r)/g)
// at speed v1 = g t1; the flight after impact k (speed e^k v1 before it) lasts 2 e^(k+1) v1 / g,
// so the impacts accumulate at t∞ = t1 + Σ_k 2 e^(k+1) v1 / g = t1 + 2 v1 e / (g (1 − e)).
double accumulation_time(double g, double y0, double r, double e) {
  const double t1 = std::sqrt(2 * (y0 - r) / g);
  const double v1 = g * t1;
  return t1 + 2 * v1 * e / (g * (1 - e));
}

class EventZenoLimit : public ::testing::TestWithParam<double> {};

TEST_P(EventZenoLimit, ReportsTheAccumulationPoint) {
  const double e = GetParam();
  const scenario::Scenario s =
      scenario::load_scenario_by_name("bouncing_ball", {{"restitution", e}});
  const RunResult run = test_support::run_with_scenario_defaults("event", s);
  const double expected =
      accumulation_time(s.parameter("g"), s.parameter("height"), s.parameter("radius"), e);

  const auto limit =
      std::find_if(run.events.begin(), run.events.end(),
                   [](const output::EventRecord& r) { return r.kind == "zeno_limit"; });
  ASSERT_NE(limit, run.events.end()) << "no zeno_limit event, e = " << e;
  EXPECT_EQ(limit->contact, "ball-ground");
  // The prediction t_k + Δt/(1 − e) is exact for a ballistic flight; what remains is CVODE's
  // error in the state at the cut-off impact (relative 1e-10 on speeds of order 1 m/s),
  // amplified by 2/(g (1 − e)) ≤ 2 s²/m: well below 1e-8 s.
  EXPECT_NEAR(limit->t, expected, 1e-8) << "e = " << e;
  EXPECT_TRUE(std::is_sorted(run.events.begin(), run.events.end(),
                             [](const auto& a, const auto& b) { return a.t < b.t; }));

  const auto line = std::find_if(run.summary.begin(), run.summary.end(), [](const auto& kv) {
    return kv.first.find("zeno limit") != std::string::npos;
  });
  ASSERT_NE(line, run.summary.end());
  EXPECT_NEAR(std::stod(line->second), expected, 1e-8);

  const compare::NamedValues errors = compare::analytic_errors(s, run);
  const auto error = std::find_if(errors.begin(), errors.end(), [](const auto& kv) {
    return kv.first == "accumulation_time_error";
  });
  ASSERT_NE(error, errors.end());
  EXPECT_NEAR(error->second, limit->t - s.analytic("t_inf"), 1e-15);
  EXPECT_LE(std::abs(error->second), 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Restitutions, EventZenoLimit, ::testing::Values(0.5, 0.7, 0.9));

}  // namespace
}  // namespace impactbench::engines::event_driven
