// A spatial scene on Siconos: the spinning sphere (sphere_spin), Siconos' MoreauJeanOSI with a
// FrictionContact of dimension 3 (fc3d nsgs) on our own model of the sphere
// (siconos_system_engine.hpp). For a sphere the velocity-level dynamics in (v, ω) are linear:
// the inertia is isotropic, so there is no gyroscopic term and the orientation enters neither
// the mass nor the contact.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "lib/scenario/scenario.hpp"
#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/reference_engine_runs.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

engines::RunResult run(const std::string& engine, const scenario::Scenario& s) {
  return adapters::run_engine(engine, s, engines::resolve_run_options(engine, s));
}

TEST(SiconosSphereSpin, RollsAtTheClosedFormFromTheStepOfTStar) {
  // While the contact point slips, each step's friction impulse is μ m g h against the slip,
  // whose direction stays fixed (the slip c = v + ω × (−R ẑ) only shrinks: ċ = −(7/2) μ g ĉ),
  // so with θ = 1/2 the slip falls linearly and stops in the step holding t* = 2|c0|/(7 μ g);
  // from then on the sphere rolls. The impulses act at the contact point, so the angular
  // momentum about it is kept, and the rolling velocities are the closed form's
  // v0 − (2/7) c0 whatever the step: off only by the solver's tolerance, 1e-10 relative on
  // impulses of size μ m g h, i.e. at most 1e-10 μ g h (1 + m R²/I) = 3.5e-10 μ g h in velocity
  // per step, summed over the n = T/h steps.
  const auto s = scenario::load_scenario_by_name("sphere_spin");
  const auto r = run("siconos", s);
  const double h = s.dt, mu = s.parameter("friction"), g = s.parameter("g");
  const double radius = s.parameter("radius");
  const auto& names = r.trajectory.velocity_names;
  const Eigen::Index vx = test_support::column_index(names, "ball.vx");
  const Eigen::Index vy = test_support::column_index(names, "ball.vy");
  const Eigen::Index wx = test_support::column_index(names, "ball.wx");
  const Eigen::Index wy = test_support::column_index(names, "ball.wy");
  const auto& samples = r.trajectory.samples;
  const auto rolling = std::find_if(samples.begin(), samples.end(), [&](const auto& sample) {
    return std::hypot(sample.v[vx] - radius * sample.v[wy], sample.v[vy] + radius * sample.v[wx]) <
           1e-9;
  });
  ASSERT_NE(rolling, samples.end());
  const double t_star = s.analytic("t_star");
  EXPECT_GE(rolling->t, t_star - 1e-12);
  EXPECT_LE(rolling->t, t_star + h + 1e-12);

  const double steps = s.duration / h;
  const double bound = steps * 3.5e-10 * mu * g * h;
  const auto& last = samples.back();
  const double error =
      std::hypot(last.v[vx] - s.analytic("final_vx"), last.v[vy] - s.analytic("final_vy"));
  std::printf(
      "siconos sphere_spin: rolling from %.4f s (t* %.6f s), final velocity error %.3g "
      "m/s (bound %.3g)\n",
      rolling->t, t_star, error, bound);
  EXPECT_LE(error, bound);
  EXPECT_NEAR(last.v[wx], s.analytic("final_wx"), bound / radius);
  EXPECT_NEAR(last.v[wy], s.analytic("final_wy"), bound / radius);
}

TEST(SiconosSphereSpin, AgreesWithOurMoreauJeanToTheSolversTolerance) {
  // The same scheme (θ = 1/2, the contact active from the first step, exact Coulomb disk) on
  // the same linear dynamics; both solve each step's friction problem by Gauss-Seidel to a
  // relative tolerance of 1e-10, not exactly, so their impulses may differ by that much of
  // μ m g h: velocities by at most 2 · 3.5e-10 μ g h per step (as above, both sides), summed
  // over the n steps, and positions by at most that times T.
  const auto s = scenario::load_scenario_by_name("sphere_spin");
  engines::SettingsRequest ours_request;
  ours_request.options = {{"activation_horizon", "0.5"}, {"activation_tolerance", "1e-9"}};
  const auto ours =
      adapters::run_engine("moreau", s, engines::resolve_run_options("moreau", s, ours_request));
  const auto siconos = run("siconos", s);
  ASSERT_EQ(ours.trajectory.samples.size(), siconos.trajectory.samples.size());
  ASSERT_EQ(ours.trajectory.velocity_names, siconos.trajectory.velocity_names);
  ASSERT_EQ(ours.trajectory.position_names, siconos.trajectory.position_names);
  double position_gap = 0.0, velocity_gap = 0.0;
  for (std::size_t k = 0; k < ours.trajectory.samples.size(); ++k) {
    const auto& a = ours.trajectory.samples[k];
    const auto& b = siconos.trajectory.samples[k];
    position_gap = std::max(position_gap, (a.q - b.q).cwiseAbs().maxCoeff());
    velocity_gap = std::max(velocity_gap, (a.v - b.v).cwiseAbs().maxCoeff());
  }
  std::printf("siconos vs moreau on sphere_spin: max |dq| %.3g, max |dv| %.3g\n", position_gap,
              velocity_gap);
  const double per_step = 2 * 3.5e-10 * s.parameter("friction") * s.parameter("g") * s.dt;
  const double velocity_bound = per_step * s.duration / s.dt;
  EXPECT_LE(velocity_gap, velocity_bound);
  EXPECT_LE(position_gap, velocity_bound * s.duration);
}

TEST(SiconosSphereSpin, RefusesThePlanarSolvers) {
  // fc3d is solved by nsgs alone: lemke, enum and cpg are planar (fc2d) solvers.
  test_support::TemporaryDirectory work("impactbench_siconos_sphere");
  test_support::TemporaryDirectory capture("impactbench_siconos_sphere_capture");
  for (const std::string solver : {"lemke", "enum", "cpg"}) {
    const auto outcome = test_support::run_program(
        IMPACTBENCH_CLI, "run sphere_spin --engine siconos --solver " + solver + " --out t.csv",
        capture.path(), "", work.path());
    EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
    EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << outcome.err;
    EXPECT_NE(outcome.err.find("fc3d nsgs only"), std::string::npos) << outcome.err;
    EXPECT_TRUE(std::filesystem::is_empty(work.path())) << solver;
  }
}

}  // namespace
}  // namespace impactbench
