// A box that turns on Siconos: the rocking block, run as our own planar model
// (siconos_system_engine.hpp: the contact relations are the model's, nonlinear in the angle),
// against Housner's closed form.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "lib/scenario/scenario.hpp"
#include "tests/support/engines/reference_engine_runs.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

TEST(SiconosRockingBlock, FirstImpactFollowsHousner) {
  // The block falls about its left corner and lands on its right one (e = 0, no slip). The
  // impact is taken in the step that starts at t_k with the corner's gap y_k + γ h ẏ_k <= 0
  // (γ = 1/2) for the first time: t_k lies between h before the true landing and h/2 after it
  // (the step before, y + h ẏ/2 > 0, moved the corner by h ẏ). While falling |ω| grows at
  // most at ω̇_max = (3 g / (4 R)) sin α (the block about a corner: I = (4/3) m R², the
  // weight's lever arm R sin(α − θ) <= R sin α), so |ω(t_k)| is the closed form's pre-impact
  // speed within [−h ω̇_max, h ω̇_max / 2]; the θ-method's own error over the 0.3 s fall is
  // second order, 1e-9 rad/s at h = 1e-4, and 1e-6 rad/s covers it. Over the impact step
  // gravity changes ω by at most h ω̇_max on either side, so the ratio ω_k+1/ω_k is Housner's
  // within 2 h ω̇_max / |ω_k|.
  const auto s = scenario::load_scenario_by_name("rocking_block");
  engines::SettingsRequest request;
  request.duration = 0.5;
  const auto r =
      adapters::run_engine("siconos", s, engines::resolve_run_options("siconos", s, request));
  const double h = s.dt, g = s.parameter("g");
  const double width = s.parameter("width"), height = s.parameter("height");
  const double radius = std::hypot(width, height) / 2, alpha = std::atan(width / height);
  const double omega_dot_max = 3 * g / (4 * radius) * std::sin(alpha);

  const auto impact = std::find_if(r.events.begin(), r.events.end(),
                                   [](const auto& e) { return e.kind == "impact"; });
  ASSERT_NE(impact, r.events.end());
  const auto& samples = r.trajectory.samples;
  const auto after = std::find_if(samples.begin(), samples.end(), [&](const auto& sample) {
    return std::abs(sample.t - impact->t) < 1e-9;
  });
  ASSERT_NE(after, samples.end());
  ASSERT_NE(after, samples.begin());
  const auto before = after - 1;
  ASSERT_NEAR(after->t - before->t, h, 1e-12);  // every step sampled
  const Eigen::Index omega = test_support::column_index(r.trajectory.velocity_names, "block.omega");
  const double w0 = before->v[omega], w1 = after->v[omega];
  const double expected = s.analytic("impact_omega", 0);
  std::printf(
      "siconos rocking_block: impact at %.4f s, |omega| %.6f vs %.6f, ratio %.6f vs "
      "Housner %.6f\n",
      impact->t, std::abs(w0), expected, w1 / w0, s.analytic("housner_ratio"));
  EXPECT_LE(std::abs(w0), expected + h * omega_dot_max / 2 + 1e-6);
  EXPECT_GE(std::abs(w0), expected - h * omega_dot_max - 1e-6);
  EXPECT_NEAR(w1 / w0, s.analytic("housner_ratio"), 2 * h * omega_dot_max / std::abs(w0));
}

}  // namespace
}  // namespace impactbench
