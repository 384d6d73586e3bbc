// Siconos' event-driven scheme (--engine siconos --option scheme=event_driven): LsodarOSI between
// events, Newton's impact law at them. On the bouncing ball, against the closed form with a
// bound built from the Lsodar tolerances the run set, and against our event engine.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lib/output/number_text.hpp"
#include "lib/scenario/scenario.hpp"
#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/reference_engine_runs.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

using Options = std::vector<std::pair<std::string, std::string>>;

engines::RunResult run(const std::string& engine, const scenario::Scenario& s,
                       const Options& options, double duration = 0.0) {
  engines::SettingsRequest request;
  request.options = options;
  if (duration > 0.0) request.duration = duration;
  return adapters::run_engine(engine, s, engines::resolve_run_options(engine, s, request));
}

std::vector<output::EventRecord> of_kind(const engines::RunResult& r, const std::string& kind) {
  std::vector<output::EventRecord> events;
  for (const auto& e : r.events)
    if (e.kind == kind) events.push_back(e);
  return events;
}

// Lsodar's error control (itol = 1, scalar tolerances) holds the max norm of each step's local
// error estimate, weighted by rtol |x_i| + atol, at most 1 (its documentation): every state
// component's local error is at most rtol |x_i| + atol. Summed over the run's S steps, velocity
// errors stay within ε_v = S (rtol v1 + atol) (|v| <= v1 throughout; an impact multiplies an
// error by e <= 1 and a flight carries it unchanged), and height errors within
// ε_y = S (rtol y0 + atol) + ε_v t (a velocity error moves the height by at most itself times
// the elapsed time t).
struct LsodarBound {
  double epsilon_v = 0.0;
  double epsilon_y = 0.0;
};

LsodarBound lsodar_bound(long steps, double rtol, double atol, double v1, double y0, double t) {
  LsodarBound b;
  b.epsilon_v = static_cast<double>(steps) * (rtol * v1 + atol);
  b.epsilon_y = static_cast<double>(steps) * (rtol * y0 + atol) + b.epsilon_v * t;
  return b;
}

class SiconosEventDrivenBall : public testing::TestWithParam<std::pair<double, double>> {};

TEST_P(SiconosEventDrivenBall, ImpactsAndFlightsMatchTheClosedForm) {
  const auto s = scenario::load_scenario_by_name("bouncing_ball");
  const auto [rtol, atol] = GetParam();
  const double e = s.parameter("restitution"), g = s.parameter("g"), m = s.parameter("mass");
  const double v1 = s.analytic("v_first", 0), y0 = s.parameter("height");
  // Compared while flights last at least 10 ms (impact k at speed e^k v1, followed by a flight
  // of 2 e^(k+1) v1/g): nearer the accumulation point the impacts are Zeno's.
  int k_end = 0;
  while (2 * std::pow(e, k_end + 1) * v1 / g >= 1e-2) ++k_end;
  const double t_end = s.analytic("impact_time", k_end);
  const auto r = run("siconos", s,
                     {{"scheme", "event_driven"},
                      {"rtol", output::number_text(rtol)},
                      {"atol", output::number_text(atol)}},
                     t_end);
  const LsodarBound bound = lsodar_bound(r.step_count, rtol, atol, v1, y0, t_end);
  std::printf("rtol %g atol %g: %ld Lsodar steps to t = %.6g s, eps_v %.3g m/s, eps_y %.3g m\n",
              rtol, atol, r.step_count, t_end, bound.epsilon_v, bound.epsilon_y);
  ASSERT_GT(r.step_count, 0);

  const auto impacts = of_kind(r, "impact");
  ASSERT_GE(static_cast<int>(impacts.size()), k_end);
  double worst_time = 0.0, worst_impulse = 0.0;
  for (int k = 0; k < k_end; ++k) {
    // Impact k ends k flights of 2 v_j/g, each off by at most 2 ε_v/g, and is located where
    // the height, off by at most ε_y, reaches the ground at speed e^k v1.
    const double speed = s.analytic("impact_speed", k);
    const double time_bound = 2 * k * bound.epsilon_v / g + bound.epsilon_y / speed;
    const double time_error = std::abs(impacts[k].t - s.analytic("impact_time", k));
    EXPECT_LE(time_error, time_bound) << "impact " << k;
    // Newton's law: the impulse is m (1 + e) times the approach speed.
    const double impulse_error = std::abs(impacts[k].impulse_n - m * (1 + e) * speed);
    EXPECT_LE(impulse_error, m * (1 + e) * bound.epsilon_v) << "impact " << k;
    worst_time = std::max(worst_time, time_error);
    worst_impulse = std::max(worst_impulse, impulse_error);
  }

  // Apex heights: in flight k the energy is m g apex_k, so every sample's E/(m g) is apex_k
  // within ε_y + v1 ε_v/g (E moves by m g δy + m v δv).
  const auto& samples = r.trajectory.samples;
  double worst_apex = 0.0;
  int flights_seen = 0;
  for (int k = 0; k < k_end; ++k) {
    const double from = k == 0 ? 0.0 : s.analytic("impact_time", k - 1);
    const double to = s.analytic("impact_time", k);
    const double apex = s.analytic("apex", k);
    int in_flight = 0;
    for (const auto& sample : samples) {
      // Samples a step clear of the impacts (whose times are off by far less than that).
      if (sample.t < from + s.dt || sample.t > to - s.dt) continue;
      const double error = std::abs(sample.energy / (m * g) - apex);
      EXPECT_LE(error, bound.epsilon_y + v1 * bound.epsilon_v / g) << "flight " << k;
      worst_apex = std::max(worst_apex, error);
      ++in_flight;
    }
    flights_seen += in_flight > 0;
  }
  EXPECT_EQ(flights_seen, k_end);
  std::printf("  %d impacts: max |dt| %.3g s, max |dimpulse| %.3g N s, max |dapex| %.3g m\n", k_end,
              worst_time, worst_impulse, worst_apex);
}

// Siconos' defaults, and 100 times looser.
INSTANTIATE_TEST_SUITE_P(LsodarTolerances, SiconosEventDrivenBall,
                         testing::Values(std::pair{1e-12, 1e-14}, std::pair{1e-10, 1e-12}),
                         [](const auto& value) { return value.index == 0 ? "tight" : "loose"; });

TEST(SiconosEventDriven, BallAgreesWithOurEventEngineAndComesToRest) {
  // Our event engine's impact times are within 1e-9 t of the closed form
  // (event_scenarios_test.cpp); Siconos' within the bound above, here below 1e-8 s for the
  // default tolerances; so the two agree within 1e-9 t + 1e-8 s while flights last 10 ms.
  const auto s = scenario::load_scenario_by_name("bouncing_ball");
  const double e = s.parameter("restitution"), g = s.parameter("g");
  const double v1 = s.analytic("v_first", 0);
  const auto siconos = run("siconos", s, {{"scheme", "event_driven"}});
  const auto ours = run("event", s, {});
  const auto a = of_kind(siconos, "impact"), b = of_kind(ours, "impact");
  int k_end = 0;
  while (2 * std::pow(e, k_end + 1) * v1 / g >= 1e-2) ++k_end;
  ASSERT_GE(static_cast<int>(std::min(a.size(), b.size())), k_end);
  for (int k = 0; k < k_end; ++k) {
    EXPECT_NEAR(a[k].t, b[k].t, 1e-9 * b[k].t + 1e-8) << "impact " << k;
    EXPECT_NEAR(a[k].impulse_n, b[k].impulse_n, 1e-8) << "impact " << k;
  }
  // Past the accumulation point both rest on the ground. Siconos closes a contact whose gap is
  // within its event tolerance (2.2e-12 m by default) and then holds it at the acceleration
  // level, so the gap drifts by Lsodar's error: the last sample is at the rest height within
  // that tolerance plus ε_y, at rest within ε_v (bound above, Siconos' default tolerances).
  const LsodarBound bound =
      lsodar_bound(siconos.step_count, 1e-12, 1e-14, v1, s.parameter("height"), s.duration);
  const auto& last = siconos.trajectory.samples.back();
  EXPECT_GT(last.t, s.analytic("t_inf", 0));
  EXPECT_NEAR(last.q[1], s.analytic("rest_height", 0), 2.220446049250313e-12 + bound.epsilon_y);
  EXPECT_NEAR(last.v[1], 0.0, bound.epsilon_v);
  // Siconos closes the contact (index set 2) after its last impact: one impact event ending
  // in a closed ("slip") mode, before t_inf.
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a.back().to_mode, "slip");
  EXPECT_LT(a.back().t, s.analytic("t_inf", 0));
  std::printf("siconos event_driven: %zu impacts, last at %.12g s (t_inf %.12g s); ours %zu\n",
              a.size(), a.back().t, s.analytic("t_inf", 0), b.size());
}

TEST(SiconosEventDriven, RefusesBadSettings) {
  test_support::expect_refused_settings("siconos", "bouncing_ball",
                                        {{"scheme", "event"},
                                         {"rtol", "0"},
                                         {"rtol", "2"},
                                         {"atol", "0"},
                                         {"atol", "-1e-9"},
                                         {"event_tolerance", "0"},
                                         {"event_tolerance", "nan"}});
}

class SiconosEventDrivenCli : public testing::Test {
 protected:
  test_support::CliOutcome run_cli(const std::string& arguments) const {
    return test_support::run_program(IMPACTBENCH_CLI, arguments, capture_.path(), "", work_.path());
  }
  void expect_refused(const test_support::CliOutcome& outcome, const std::string& message) const {
    EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
    ASSERT_FALSE(outcome.err.empty());
    EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << outcome.err;  // one line
    EXPECT_NE(outcome.err.find(message), std::string::npos) << outcome.err;
    EXPECT_TRUE(std::filesystem::is_empty(work_.path())) << "a refused run left a file";
  }
  test_support::TemporaryDirectory work_{"impactbench_siconos_ed"};
  test_support::TemporaryDirectory capture_{"impactbench_siconos_ed_capture"};
};

TEST_F(SiconosEventDrivenCli, RefusesFrictionAndInputs) {
  // Frictionless only: the sliding block has μ = 0.5.
  expect_refused(run_cli("run sliding_block --engine siconos --option scheme=event_driven "
                         "--out t.csv --events e.csv"),
                 "scheme event_driven states frictionless contacts only");
  // Without friction the incline still has its push: inputs are not applied.
  expect_refused(run_cli("run incline --engine siconos --option scheme=event_driven "
                         "--set friction=0 --out t.csv"),
                 "scheme event_driven applies no force inputs");
  // Past t_inf at rtol = 1e-10 Siconos chains impacts without end (the gap after each stays
  // within event_tolerance, the contact never closes): stopped after 100,000 of them.
  expect_refused(run_cli("run bouncing_ball --engine siconos --option scheme=event_driven "
                         "--option rtol=1e-10 --out t.csv --events e.csv"),
                 "nonsmooth events between two samples");
  // The plank-box is stated for Moreau-Jean only.
  expect_refused(run_cli("run plank_box --engine siconos --option scheme=event_driven "
                         "--out t.csv --events e.csv"),
                 "scheme event_driven states disks and boxes against planes only");
  // Spatial scenes are stated for Moreau-Jean only.
  expect_refused(run_cli("run sphere_spin --engine siconos --option scheme=event_driven "
                         "--out t.csv"),
                 "of spatial scenes only one sphere is stated, with scheme moreau_jean");
}

}  // namespace
}  // namespace impactbench
