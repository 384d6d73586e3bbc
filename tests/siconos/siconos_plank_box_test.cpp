// The plank–box on Siconos (--engine siconos on plank_box): Siconos' MoreauJeanOSI integrating
// our own model of it (tools/engines/siconos/siconos_system_engine.hpp). Checked against the
// static balance of the loaded plank, a closed form, and against our Moreau–Jean.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lib/output/number_text.hpp"
#include "lib/scenario/scenario.hpp"
#include "tests/support/engines/reference_engine_runs.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

using Options = std::vector<std::pair<std::string, std::string>>;

engines::RunResult run(const std::string& engine, const scenario::Scenario& s, double dt,
                       double duration, const Options& options) {
  engines::SettingsRequest request;
  request.dt = dt;
  request.duration = duration;
  request.options = options;
  return adapters::run_engine(engine, s, engines::resolve_run_options(engine, s, request));
}

TEST(SiconosPlankBox, ComesToTheStaticBalanceOfTheLoadedPlank) {
  // At rest the box's weight reaches the plank through the contacts as a force −m_B g ŷ whose
  // line of action passes through the box's centre (the box's torque balance), so the plank
  // rests where  k_P φ + (m_P g L_P/2) cos φ + m_B g x_B = 0,  x_B the box centre's x. At a
  // fixed point of the θ-method (v = 0) the discrete balance is this one exactly; what is left
  // after T is (a) the oscillation of the plank with the box stuck on it, decaying as
  // e^(−b_P T/(2 I)), I = I_P + J_B + m_B |p_B|² their inertia about the hinge, from an
  // amplitude below 0.1 rad, times k_P + m_P g L_P/2 (the balance's slope); (b) Siconos' Newton
  // tolerance on the step's residual, an impulse [N·s], i.e. a force error up to tolerance/h.
  const auto s = scenario::load_scenario_by_name("plank_box");
  const double h = s.dt, duration = 20.0;
  const auto r = run("siconos", s, h, duration, {});
  const auto& last = r.trajectory.samples.back();
  ASSERT_NEAR(last.t, duration, 1e-9);
  const auto& names = r.trajectory.position_names;
  const double phi = last.q[test_support::column_index(names, "plank.phi")];
  const double x_b = last.q[test_support::column_index(names, "box.x")];
  const double g = s.parameter("g"), m_b = s.parameter("m_B"), m_p = s.parameter("m_P");
  const double l_p = s.parameter("L_P"), k_p = s.parameter("k_P"), b_p = s.parameter("b_P");
  const double c = m_p * g * l_p / 2;
  const double balance = k_p * phi + c * std::cos(phi) + m_b * g * x_b;

  const double y_b = last.q[test_support::column_index(names, "box.y")];
  const double inertia =
      s.analytic("hinge_inertia") + s.analytic("box_inertia") + m_b * (x_b * x_b + y_b * y_b);
  const double oscillation = (k_p + c) * 0.1 * std::exp(-b_p * duration / (2 * inertia));
  const double newton = 1e-10 / h;  // NewtonLoop's tolerance (siconos_lagrangian_model.hpp)
  std::printf(
      "plank_box on siconos at t = %g s: phi %.12g rad, x_B %.12g m, balance %.3g N m "
      "(bound %.3g oscillation + %.3g Newton)\n",
      duration, phi, x_b, balance, oscillation, newton);
  EXPECT_LE(std::abs(balance), oscillation + newton);
  // The box's own term is far above that bound: the balance is checked with the box on it.
  EXPECT_GT(m_b * g * x_b, 1e6 * (oscillation + newton));
}

TEST(SiconosPlankBox, ConvergesWithOurMoreauJeanAtFirstOrder) {
  // Both are Moreau–Jean with θ = 1/2 and the same activation rule (γ = 1/2, threshold 1e-9 m)
  // on the same model, so the same impacts happen at the same steps. They differ in how a step
  // treats the nonlinear forces (ours linearly implicit, Siconos Newton-converged) and where
  // the contact Jacobians are taken (ours at q_k, Siconos at its iterate): both first-order
  // schemes of the same solution, so their positions differ by O(h): at h/4 by at most half of
  // what they differ at h (a first-order difference shrinks by 4).
  const auto s = scenario::load_scenario_by_name("plank_box");
  const Options ours_options = {
      {"theta", "0.5"}, {"activation_horizon", "0.5"}, {"activation_tolerance", "1e-9"}};
  const Options siconos_options = {
      {"theta", "0.5"}, {"gamma", "0.5"}, {"activation_threshold", "1e-9"}};
  const std::vector<std::string> coordinates = {"box.x", "box.y", "box.theta", "plank.phi"};
  std::vector<std::vector<double>> gaps;
  for (const double h : {1e-3, 2.5e-4}) {
    const auto ours = run("moreau", s, h, 1.0, ours_options);
    const auto siconos = run("siconos", s, h, 1.0, siconos_options);
    ASSERT_EQ(ours.trajectory.samples.size(), siconos.trajectory.samples.size());
    std::vector<double> gap(coordinates.size(), 0.0);
    for (std::size_t c = 0; c < coordinates.size(); ++c) {
      const Eigen::Index i =
          test_support::column_index(ours.trajectory.position_names, coordinates[c]);
      ASSERT_EQ(i, test_support::column_index(siconos.trajectory.position_names, coordinates[c]));
      for (std::size_t k = 0; k < ours.trajectory.samples.size(); ++k)
        gap[c] = std::max(
            gap[c], std::abs(ours.trajectory.samples[k].q[i] - siconos.trajectory.samples[k].q[i]));
    }
    gaps.push_back(gap);
    // The same impacts (contact and step), with impulses that differ by the O(h) above.
    ASSERT_EQ(ours.events.size(), siconos.events.size()) << "h = " << h;
    for (std::size_t e = 0; e < ours.events.size(); ++e) {
      EXPECT_EQ(ours.events[e].contact, siconos.events[e].contact);
      EXPECT_EQ(ours.events[e].kind, siconos.events[e].kind);
      EXPECT_NEAR(ours.events[e].t, siconos.events[e].t, 1e-9);
    }
    std::printf(
        "h = %g: max |d box.x| %.3g, |d box.y| %.3g, |d box.theta| %.3g, "
        "|d plank.phi| %.3g; %zu events\n",
        h, gap[0], gap[1], gap[2], gap[3], ours.events.size());
  }
  for (std::size_t c = 0; c < coordinates.size(); ++c) {
    EXPECT_GT(gaps[0][c], 0.0) << coordinates[c];  // different schemes: not the same numbers
    EXPECT_LE(gaps[1][c], gaps[0][c] / 2) << coordinates[c];
  }
}

TEST(SiconosPlankBox, IsListedAndRefusesTheEventDrivenScheme) {
  const auto s = scenario::load_scenario_by_name("plank_box");
  EXPECT_TRUE(s.supports_engine("siconos"));
  try {
    run("siconos", s, s.dt, 0.1, {{"scheme", "event_driven"}});
    ADD_FAILURE() << "event_driven ran on plank_box";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("scheme event_driven"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace impactbench
