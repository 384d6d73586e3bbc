// Siconos 4.4 (--engine siconos), built and run only where the Siconos kernel is installed
// (tests/CMakeLists.txt). Siconos' MoreauJeanOSI is the scheme our Moreau–Jean implements: given
// the same θ, the same activation rule (y_k + γ h ẏ_k ≤ threshold) and the same contact law,
// the two compute the same operations on the same numbers, so their trajectories agree to
// round-off, not to a discretisation error.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lib/scenario/scenario.hpp"
#include "tests/support/engines/reference_engine_runs.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

using Options = std::vector<std::pair<std::string, std::string>>;

engines::RunResult run(const std::string& engine, const scenario::Scenario& s, double dt,
                       const Options& options) {
  engines::SettingsRequest request;
  request.dt = dt;
  request.options = options;
  return adapters::run_engine(engine, s, engines::resolve_run_options(engine, s, request));
}

std::vector<output::EventRecord> impacts_before(const engines::RunResult& r, double t_end) {
  std::vector<output::EventRecord> impacts;
  for (const auto& e : r.events)
    if (e.kind == "impact" && e.t < t_end) impacts.push_back(e);
  return impacts;
}

class SiconosGamma : public testing::TestWithParam<std::string> {};

TEST_P(SiconosGamma, BouncingBallAgreesWithOurMoreauJeanToRoundOff) {
  // e = 0.9, h = 5e-3, θ = 1/2, the same γ, activation threshold 0 on both sides.
  const auto s = scenario::load_scenario_by_name("bouncing_ball");
  const double h = 5e-3;
  const std::string gamma = GetParam();
  const auto ours =
      run("moreau", s, h,
          {{"theta", "0.5"}, {"activation_horizon", gamma}, {"activation_tolerance", "0"}});
  const auto siconos =
      run("siconos", s, h, {{"theta", "0.5"}, {"gamma", gamma}, {"activation_threshold", "0"}});

  // Compared while every flight lasts at least 10 steps: flight k (after impact k − 1) lasts
  // 2 e^k v1/g, so the comparison ends at the first impact k after which a flight is shorter.
  // Nearer the accumulation point the activation test y + γhẏ ≤ 0 is decided on gaps of the
  // size of the round-off, and either scheme may take the other branch.
  const double e = s.parameter("restitution"), g = s.parameter("g");
  const double v1 = s.analytic("v_first", 0);
  int k = 0;
  while (2 * std::pow(e, k + 1) * v1 / g >= 10 * h) ++k;
  const double t_end = s.analytic("impact_time", k);
  ASSERT_GT(t_end, 0.9 * s.analytic("t_inf", 0));  // most of the way to the accumulation point

  const auto& a = ours.trajectory;
  const auto& b = siconos.trajectory;
  const Eigen::Index y = test_support::column_index(a.position_names, "ball.y");
  const Eigen::Index vy = test_support::column_index(a.velocity_names, "ball.vy");
  ASSERT_EQ(y, test_support::column_index(b.position_names, "ball.y"));
  double height_gap = 0.0, speed_gap = 0.0;
  int compared = 0;
  for (std::size_t i = 0; i < std::min(a.samples.size(), b.samples.size()); ++i) {
    // Both sample every step; our t accumulates h, Siconos' is k h.
    ASSERT_NEAR(a.samples[i].t, b.samples[i].t, 1e-12);
    if (a.samples[i].t > t_end) break;
    height_gap = std::max(height_gap, std::abs(a.samples[i].q[y] - b.samples[i].q[y]));
    speed_gap = std::max(speed_gap, std::abs(a.samples[i].v[vy] - b.samples[i].v[vy]));
    ++compared;
  }
  // Round-off: heights of order 1 m, speeds up to v1 ≈ 4.2 m/s, each step a few operations
  // on them (ulp 2.2e-16 m and 8.9e-16 m/s): tens of ulps, far from the O(h) = 5e-3 of
  // discretisation errors.
  EXPECT_GT(compared, 1000);
  EXPECT_LT(height_gap, 1e-14);
  EXPECT_LT(speed_gap, 1e-13);

  // The same impacts, at the same steps, with the same impulses.
  const auto ia = impacts_before(ours, t_end), ib = impacts_before(siconos, t_end);
  ASSERT_EQ(ia.size(), ib.size());
  // Impacts 0..k−1 happen before t_end; the sampled ones lag or lead by about a step, so the
  // last of them may fall past it.
  EXPECT_GE(static_cast<int>(ia.size()), k - 1);
  for (std::size_t i = 0; i < ia.size(); ++i) {
    EXPECT_NEAR(ia[i].t, ib[i].t, 1.5e-13) << "impact " << i;
    EXPECT_NEAR(ia[i].impulse_n, ib[i].impulse_n, 1e-13 * s.parameter("mass") * v1 * (1 + e))
        << "impact " << i;
  }
  std::printf(
      "siconos vs moreau, gamma %s: %d samples to t = %.6g s, max |dy| = %.3g m, "
      "max |dvy| = %.3g m/s, %zu impacts\n",
      gamma.c_str(), compared, t_end, height_gap, speed_gap, ia.size());
}

// γ = 1/2 is Siconos' own; 0 activates on the gap alone, 1 looks a full step ahead.
INSTANTIATE_TEST_SUITE_P(ActivationForecasts, SiconosGamma, testing::Values("0.5", "0", "1"),
                         [](const auto& value) {
                           return value.index == 0 ? "half" : value.index == 1 ? "zero" : "one";
                         });

TEST(SiconosEngine, SlidingBlockStopsAtTheThetaMethodLimit) {
  // Derived: while sliding, the step's Coulomb impulse is μ m g h (both corners active, exact
  // 2D friction), so v_k = v0 − k a h (a = μ g) and, with θ = 1/2, x_k = v0 t_k − a t_k²/2:
  // the nodes lie on the exact motion. With n = v0/(a h), N = ⌊n⌋ and f = n − N > 0, the
  // block sticks in step N + 1: t_stop = (N + 1) h and x_stop = x_N + h v_N/2 with
  // v_N = f a h, i.e. x_stop = v0²/(2a) + a h² f (1 − f)/2.
  const auto s = scenario::load_scenario_by_name("sliding_block");
  const double h = s.dt, v0 = s.parameter("v0");
  const double a = s.parameter("friction") * s.parameter("g");
  const double n = v0 / (a * h), f = n - std::floor(n);
  ASSERT_GT(f, 1e-6);                                           // the stop does not fall on a node
  for (const std::string solver : {"nsgs", "lemke", "enum"}) {  // cpg does not converge here
    const auto r = run("siconos", s, h, {{"solver", solver}});
    const Eigen::Index x = test_support::column_index(r.trajectory.position_names, "block.x");
    const Eigen::Index vx = test_support::column_index(r.trajectory.velocity_names, "block.vx");
    const auto stop =
        std::find_if(r.trajectory.samples.begin(), r.trajectory.samples.end(),
                     [&](const auto& sample) { return std::abs(sample.v[vx]) < 1e-9; });
    ASSERT_NE(stop, r.trajectory.samples.end()) << solver;
    // The step count is exact. 1e-10 m covers NSGS' tolerance: 1e-10 relative on the step's
    // impulse μ m g h ≈ 5e-3 N·s is ≤ 5e-13 m/s per step, summed over n ≈ 408 steps and
    // integrated, h·n²/2·5e-13 ≈ 4e-11 m (Lemke and enumeration pivot: round-off only).
    EXPECT_NEAR(stop->t, (std::floor(n) + 1) * h, 1e-12) << solver;
    EXPECT_NEAR(stop->q[x], v0 * v0 / (2 * a) + a * h * h * f * (1 - f) / 2, 1e-10) << solver;
  }
}

TEST(SiconosEngine, PushedInclineSlipsAtTheThetaMethodLimit) {
  // Derived: the push c t is held over each step at t_k + h/2 (θ = 1/2), so a step that slips
  // throughout gains exactly ∫ (c t/m + a0) dt; the scheme sticks while c t_mid/m + a0 <= 0,
  // i.e. while t_mid <= t_s. If t_s lies in the first half of its step (u = t_k+1 − t_s in
  // (h/2, h]) the step slips and ends with (c/m)(u − h/2)h instead of c u²/(2m): short by
  // c (h − u)²/(2m); otherwise (w = t_k+1 − t_s in (0, h/2]) the next step is the first to
  // slip and ends short by c w²/(2m). Either way the speed afterwards lags the closed form
  // by a constant in [0, c h²/(8m)].
  const auto s = scenario::load_scenario_by_name("incline");
  const double c = s.parameter("push_rate"), m = s.parameter("mass"), h = s.dt;
  for (const std::string solver : {"nsgs", "lemke"}) {
    const auto errors =
        test_support::run_and_measure("siconos", "incline", {}, 0.0, {{"solver", solver}});
    const double error = test_support::named(errors, "slip_speed_error");
    std::printf("siconos incline (%s): slip speed error %.3g m/s, bound [-%.3g, 0]\n",
                solver.c_str(), error, c * h * h / (8 * m));
    // 1e-11 m/s: the solver's tolerance on ~2000 steps of impulses ~m g h.
    EXPECT_GE(error, -c * h * h / (8 * m) - 1e-11) << solver;
    EXPECT_LE(error, 1e-11) << solver;
  }
}

TEST(SiconosEngine, RefusesWhatItCannotState) {
  // Several bodies are not stated (the plank-box is, as our own Lagrangian system:
  // siconos_plank_box_test.cpp; so is one sphere: siconos_sphere_spin_test.cpp).
  for (const std::string name : {"newtons_cradle", "disk_pile", "sphere_pile", "box_pyramid"}) {
    const auto s = scenario::load_scenario_by_name(name);
    EXPECT_FALSE(s.supports_engine("siconos")) << name;
  }
  test_support::expect_refused_settings("siconos", "bouncing_ball",
                                        {{"theta", "0.4"},
                                         {"gamma", "1.5"},
                                         {"activation_threshold", "-1"},
                                         {"solver", "nsn_ac"},
                                         {"tolerance", "0"},
                                         {"max_iterations", "0"}});
}

}  // namespace
}  // namespace impactbench
