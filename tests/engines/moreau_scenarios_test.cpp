// Moreau–Jean on the scenario files (scenarios/*.toml) run exactly as `impactbench run
// SCENARIO --engine moreau` runs them (engine registry, the scenario's step and duration, the
// engine's default solver and settings), checked against the analytical quantities the files
// state. Bounds are the ones derived in the per-scenario tests (moreau_<scenario>_test.cpp),
// here as functions of the scenario's own dt.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/system_builder.hpp"
#include "lib/scenario/scenario.hpp"
#include "tests/support/engines/scenario_runs.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

struct ScenarioRun {
  scenario::Scenario scenario;
  RunResult result;
  /// The state after step k (steps[k]) is samples[k + 1]; samples[0] is the initial state.
  const output::TrajectorySample& after(std::size_t k) const {
    return result.trajectory.samples.at(k + 1);
  }
  const output::TrajectorySample& initial() const { return result.trajectory.samples.front(); }
  const output::TrajectorySample& final_state() const { return result.trajectory.samples.back(); }
};

ScenarioRun run_scenario(const std::string& name) {
  ScenarioRun run{scenario::load_scenario_by_name(name), {}};
  run.result = test_support::run_with_scenario_defaults("moreau", run.scenario);
  EXPECT_EQ(run.result.trajectory.samples.size(), run.result.steps.size() + 1) << name;
  return run;
}

TEST(MoreauScenarios, BouncingBallComesToRest) {
  // The apexes and impact times of the first bounces are in the closed-form suite
  // (closed_form_suite_test.cpp); here the end: after the accumulation point the ball rests.
  const auto run = run_scenario("bouncing_ball");
  const auto& sc = run.scenario;
  EXPECT_NEAR(run.final_state().q(1), sc.analytic("rest_height"), sc.dt * sc.analytic("v_first"));
  EXPECT_NEAR(run.final_state().v(1), 0.0, 1e-9);
}

TEST(MoreauScenarios, InclinePushSlipTime) {
  // The final speed is in the closed-form suite (closed_form_suite_test.cpp).
  double slip_start = -1, previous_t = 0;
  const auto run = run_scenario("incline");
  for (const auto& s : run.result.trajectory.samples) {
    if (slip_start < 0 && s.v.head<2>().norm() > 1e-9) slip_start = previous_t;
    previous_t = s.t;
  }
  const auto& sc = run.scenario;
  std::printf("incline: slip step at %.5f s vs %.5f\n", slip_start, sc.analytic("slip_time"));
  EXPECT_LE(std::abs(slip_start - sc.analytic("slip_time")), sc.dt);
}

TEST(MoreauScenarios, RockingBlockHousnerRatio) {
  // The block starts on its left corner (the pivot, loaded from the first step on); the right
  // corner lands at the first impulse on any other contact.
  double ratio = 0, omega_before = 0;
  bool found = false;
  const auto run = run_scenario("rocking_block");
  const auto& steps = run.result.steps;
  ASSERT_FALSE(steps.empty());
  std::string pivot;
  for (const auto& c : steps.front().contacts)
    if (c.impulse_n > 0) pivot = c.name;
  ASSERT_FALSE(pivot.empty()) << "no contact carries the block in the first step";
  for (std::size_t k = 1; k < steps.size() && !found; ++k) {
    for (const auto& c : steps[k].contacts) {
      if (c.name != pivot && c.impulse_n > 0) {
        found = true;
        omega_before = run.after(k - 1).v(2);
        ratio = run.after(k).v(2) / omega_before;
        break;
      }
    }
  }
  const auto& sc = run.scenario;
  ASSERT_TRUE(found);
  std::printf("rocking_block: |omega| before %.6f vs %.6f, ratio %.6f vs Housner %.6f\n",
              std::abs(omega_before), sc.analytic("impact_omega", 0), ratio,
              sc.analytic("housner_ratio"));
  EXPECT_NEAR(ratio, sc.analytic("housner_ratio"), 1e-3);
  EXPECT_NEAR(std::abs(omega_before), sc.analytic("impact_omega", 0),
              1e-3 * sc.analytic("impact_omega", 0));
}

TEST(MoreauScenarios, NewtonsCradleSequentialImpacts) {
  const auto run = run_scenario("newtons_cradle");
  const auto& sc = run.scenario;
  const int count = static_cast<int>(sc.parameter("count"));
  const Eigen::VectorXd& v = run.final_state().v;
  double momentum = 0, kinetic = 0;
  for (int i = 0; i < count; ++i) {
    momentum += sc.parameter("mass") * v(3 * i);
    kinetic += 0.5 * sc.parameter("mass") * v(3 * i) * v(3 * i);
    const double expected =
        i + 1 == count ? sc.analytic("final_speed_last") : sc.analytic("final_speed_others");
    EXPECT_NEAR(v(3 * i), expected, 1e-9) << "ball " << i;
  }
  EXPECT_NEAR(momentum, sc.analytic("momentum"), 1e-9 * sc.analytic("momentum"));
  EXPECT_NEAR(kinetic, sc.analytic("kinetic_energy"), 1e-9 * sc.analytic("kinetic_energy"));
  // Each impact is applied in the step before the gap would close: up to h early.
  const double x_last = run.final_state().q(3 * (count - 1));
  std::printf("newtons_cradle: last ball at %.6f vs %.6f\n", x_last,
              sc.analytic("last_position_end"));
  EXPECT_NEAR(x_last, sc.analytic("last_position_end"), (count - 1) * sc.parameter("v0") * sc.dt);
}

TEST(MoreauScenarios, SphereSpinRolls) {
  double roll_time = -1;
  const auto run = run_scenario("sphere_spin");
  for (const auto& step : run.result.steps) {
    // Rolling: the impulse stays strictly inside the cone once the slip has vanished.
    if (roll_time < 0 && !step.contacts.empty() && step.contacts[0].velocity_t.norm() < 1e-8)
      roll_time = step.t;
  }
  const auto& sc = run.scenario;
  const Eigen::VectorXd& v = run.final_state().v;
  std::printf("sphere_spin: rolls at %.5f s vs t* %.5f; v (%.9f, %.9f) vs (%.9f, %.9f)\n",
              roll_time, sc.analytic("t_star"), v(0), v(1), sc.analytic("final_vx"),
              sc.analytic("final_vy"));
  EXPECT_GE(roll_time - sc.analytic("t_star"), -1e-12);
  EXPECT_LT(roll_time - sc.analytic("t_star"), sc.dt);
  // The rolling velocity (vx, vy) is in the closed-form suite (closed_form_suite_test.cpp).
  EXPECT_NEAR(v(3), sc.analytic("final_wx"), 1e-7);
  EXPECT_NEAR(v(4), sc.analytic("final_wy"), 1e-7);
  EXPECT_NEAR(v(5), sc.analytic("final_wz"), 1e-7);
}

TEST(MoreauScenarios, PlankBoxDissipates) {
  const auto run = run_scenario("plank_box");
  const auto& sc = run.scenario;
  const BuiltSystem built = build_system(sc);
  // Energy, with the default explicit forces and θ = 1/2 (free_motion.cpp): forces at the
  // predictor q_θ = q_k + (h/2) v_k, velocities v_k; q_{k+1} = q_k + h v̄, v̄ = (v_k + v_{k+1})/2;
  // M Δv = h F + H r. Then ΔE splits term by term:
  //  - the box's constant weight F: ΔKE = h F·v̄ = −ΔPE, so ΔE = 0 exactly;
  //  - the hinge spring −k φ at φ_θ: ΔKE = −h k (φ_k + (h/2) φ̇_k) φ̇̄, ΔPE = k φ_k h φ̇̄ +
  //    ½ k h² φ̇̄², so ΔE = ½ k h² φ̇̄ (φ̇̄ − φ̇_k) = ¼ k h² φ̇̄ Δφ̇ (either sign);
  //  - the plank's weight torque, a spring of stiffness m_P g (L_P/2) sin φ: at most
  //    ¼ m_P g (L_P/2) h² |φ̇̄ Δφ̇|;
  //  - the explicit damper −b_P φ̇_k: ΔE = −h b_P φ̇_k φ̇̄, a rise only where φ̇ reverses;
  //  - the contact impulse r: ΔE = r·ζ̄ = ½ r·ζ_k + ½ r·ζ_{k+1}, where the second half is ≤ 0
  //    (ζ_n⁺ r_n = 0 and friction opposes ζ_t⁺) and the first is recomputed here from the
  //    recorded impulses and ζ_k = Hᵀ v_k of the model's contacts at the step's start.
  // Each step's rise is checked against the sum of the positive parts, plus 1e-10 J for the
  // contact solve (tolerance 1e-10, energies of order 1 J).
  const auto& samples = run.result.trajectory.samples;
  const double stiffness = sc.parameter("k_P");
  const double weight_stiffness = sc.parameter("m_P") * sc.parameter("g") * sc.parameter("L_P") / 2;
  const double h = sc.dt;
  const auto start_velocities = [&](std::size_t k) {
    std::map<std::string, Eigen::Vector2d> zeta;
    std::vector<model::Contact<double>> contacts;
    const auto& s = samples[k];
    built.system->find_contacts(s.q, s.v, std::numeric_limits<double>::infinity(), contacts);
    const int nv = static_cast<int>(s.v.size());
    for (const auto& c : contacts)
      zeta[c.name] = {c.normal_direction(nv).dot(s.v), c.tangent_directions(nv).col(0).dot(s.v)};
    return zeta;
  };
  double max_energy_rise = -std::numeric_limits<double>::infinity(), worst_ratio = 0.0;
  for (std::size_t k = 1; k < samples.size(); ++k) {
    const double rise = samples[k].energy - samples[k - 1].energy;
    const double rate_before = samples[k - 1].v(3);
    const double mean_rate = (rate_before + samples[k].v(3)) / 2;
    double contact_work = 0.0;
    const auto zeta = start_velocities(k - 1);
    for (const auto& c : run.result.steps[k - 1].contacts) {
      const auto found = zeta.find(c.name);
      ASSERT_NE(found, zeta.end()) << c.name;
      contact_work += 0.5 * (c.impulse_n * found->second(0) + c.impulse_t(0) * found->second(1));
    }
    const double spring = 0.25 * h * h * mean_rate * (samples[k].v(3) - rate_before);
    const double allowance = std::max(0.0, stiffness * spring) +
                             weight_stiffness * std::abs(spring) +
                             h * sc.parameter("b_P") * std::max(0.0, -rate_before * mean_rate) +
                             std::max(0.0, contact_work) + 1e-10;
    max_energy_rise = std::max(max_energy_rise, rise);
    worst_ratio = std::max(worst_ratio, rise / allowance);
  }
  // Penetration: no corner sinks deeper than one step at the largest approach speed: ζ_n =
  // w_nᵀ v of every contact the model finds at every step start, recomputed here from the
  // recorded states.
  double approach = 0.0, max_penetration = 0.0;
  std::vector<model::Contact<double>> contacts;
  for (const auto& s : samples) {
    contacts.clear();
    built.system->find_contacts(s.q, s.v, std::numeric_limits<double>::infinity(), contacts);
    for (const auto& c : contacts) {
      approach = std::max(approach, -c.normal_direction(s.v.size()).dot(s.v));
      max_penetration = std::max(max_penetration, -c.gap);
    }
  }
  std::printf(
      "plank_box: max energy rise %.2e J (worst rise / allowance %.3g), max penetration "
      "%.3e m (h * approach %.3e)\n",
      max_energy_rise, worst_ratio, max_penetration, run.scenario.dt * approach);
  EXPECT_LE(worst_ratio, 1.0);
  EXPECT_LE(max_penetration, run.scenario.dt * approach);
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
