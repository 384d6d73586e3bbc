// The free plank of the plank–box scenario (box far above it) under Moreau–Jean with the
// default settings: its small oscillation about the true equilibrium φ_eq against the damped
// oscillator's closed form converges at second order in h (the hinge damper is taken
// θ-implicitly; evaluated at v_k it made the step first order).
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

constexpr double kAmplitude = 1e-4;  // initial offset from φ_eq [rad]
constexpr double kDuration = 2.0;

// The plank (inertia J about the hinge) obeys J φ̈ + b φ̇ + k φ + c cos φ = 0 with
// c = m_P g L_P/2 (its weight at mid-length). Equilibrium: k φ_eq + c cos φ_eq = 0 (Newton's
// method below, from φ = −c/k). About it, δ = φ − φ_eq obeys J δ̈ + b δ̇ + k_eq δ = O(δ²) with
// k_eq = k − c sin φ_eq, so released at rest from δ0:
//   δ(t) = δ0 e^(−σt) (cos ω_d t + (σ/ω_d) sin ω_d t),  σ = b/(2J),  ω_d = √(k_eq/J − σ²).
// The O(δ²) term, (c/2) cos φ_eq δ², moves the motion by about (c/2) δ0²/k_eq ≈ 2.4e-10 rad =
// 2.4e-6 δ0: a floor well below the discretisation errors compared here (≥ 5e-5 δ0 at
// h = 1e-3, the midpoint rule's phase error ω³h²t/24 being 4e-4 δ0 in the worst case).
struct PlankOscillator {
  double equilibrium, sigma, omega_d;
  double offset(double t, double delta0) const {
    return delta0 * std::exp(-sigma * t) *
           (std::cos(omega_d * t) + sigma / omega_d * std::sin(omega_d * t));
  }
};

PlankOscillator oscillator(const scenario::Scenario& s) {
  const double k = s.parameter("k_P"), b = s.parameter("b_P"), m = s.parameter("m_P");
  const double L = s.parameter("L_P"), l = s.parameter("l_P");
  const double J = m * L * L / 4 + m * (L * L + l * l) / 12;
  const double c = m * s.parameter("g") * L / 2;
  double phi = -c / k;
  for (int i = 0; i < 50; ++i) phi -= (k * phi + c * std::cos(phi)) / (k - c * std::sin(phi));
  const double sigma = b / (2 * J);
  return {phi, sigma, std::sqrt((k - c * std::sin(phi)) / J - sigma * sigma)};
}

struct Errors {
  double trajectory = 0.0;  // max |δ_k − δ(t_k)| / δ0
  double crossings = 0.0;   // max error of the zero-crossing times [s]
  int crossing_count = 0;
};

Errors free_plank_errors(double h) {
  const scenario::Scenario s = scenario::load_scenario_by_name("plank_box", {{"height", 50.0}});
  engines::BuiltSystem built = engines::build_system(s);
  const PlankOscillator exact = oscillator(s);
  constexpr int kPhi = 3;  // q = (box.x, box.y, box.theta, plank.phi)
  built.q0(kPhi) = exact.equilibrium + kAmplitude;
  built.v0.setZero();
  MoreauJeanOptions options;  // the defaults, but for the step
  options.dt = h;
  options.record_impulses = false;
  MoreauJeanStepper stepper(*built.system, options);
  const int nu = built.system->num_inputs();
  const InputFunction no_input = [nu](double) { return Eigen::VectorXd::Zero(nu).eval(); };
  Errors errors;
  double t_previous = 0.0, delta_previous = kAmplitude;
  // The zero of the closed form in [lo, hi], half a period wide around a numerical zero (so it
  // holds exactly one), by bisection.
  const auto exact_crossing = [&](double lo, double hi) {
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (exact.offset(lo, 1.0) * exact.offset(mid, 1.0) <= 0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const SimulationResult result = stepper.simulate(
      built.q0, built.v0, no_input, kDuration,
      [&](const MoreauJeanState& state, const StepReport&) {
        const double delta = state.q(kPhi) - exact.equilibrium;
        errors.trajectory = std::max(
            errors.trajectory, std::abs(delta - exact.offset(state.t, kAmplitude)) / kAmplitude);
        if (state.t > 0 && delta_previous * delta < 0) {
          // Linear interpolation between the nodes: its error is O(h² δ''), and at a zero
          // δ'' = −(b/J) δ' is small: second order too.
          const double t_zero =
              t_previous + (state.t - t_previous) * delta_previous / (delta_previous - delta);
          const double half_period = M_PI / exact.omega_d;
          const double t_exact =
              exact_crossing(std::max(0.0, t_zero - half_period / 2), t_zero + half_period / 2);
          errors.crossings = std::max(errors.crossings, std::abs(t_zero - t_exact));
          ++errors.crossing_count;
        }
        t_previous = state.t;
        delta_previous = delta;
      });
  EXPECT_TRUE(result.succeeded()) << result.message;
  EXPECT_EQ(result.summary.max_active_contacts, 0);  // the box never reaches the plank
  return errors;
}

TEST(MoreauPlankDamper, FreePlankConvergesAtSecondOrderAboutItsEquilibrium) {
  std::vector<Errors> errors;
  for (const double h : {4e-3, 2e-3, 1e-3}) errors.push_back(free_plank_errors(h));
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    const double trajectory_ratio = errors[i].trajectory / errors[i + 1].trajectory;
    const double crossing_ratio = errors[i].crossings / errors[i + 1].crossings;
    // Halving h divides a second-order error by 4 (a first-order one by 2).
    EXPECT_NEAR(trajectory_ratio, 4.0, 0.4) << "h = " << 4e-3 / (1 << i);
    EXPECT_NEAR(crossing_ratio, 4.0, 0.6) << "h = " << 4e-3 / (1 << i);
    EXPECT_GE(errors[i].crossing_count, 10);  // ω_d ≈ 17.4 rad/s: 2 s hold ω_d t/π ≈ 11 zeros
    std::printf(
        "h = %g: trajectory error %.3g δ0 (ratio %.3f), zero-crossing error %.3g s "
        "(ratio %.3f)\n",
        4e-3 / (1 << i), errors[i].trajectory, trajectory_ratio, errors[i].crossings,
        crossing_ratio);
  }
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
