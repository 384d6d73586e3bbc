// The plank–box system (appendix F) under Moreau–Jean: a box dropped flat or tilted onto the
// sprung plank. Without input the only energy sources are none: the spring and damper are
// taken linearly implicitly (θ = 1/2, trapezoidal on the linear part) and impacts with e < 1
// and friction dissipate, so the energy must not rise across any step beyond what the solver
// tolerance and the linearisation of the plank's gravity torque allow. Penetration comes from
// impact steps (at most h times the approach speed) and shrinks with h.
// Solved with lemke: once the box rests almost flat on the moving plank, the two corners'
// tangential rows are nearly parallel, W is nearly singular, and the iterative solvers' residual
// stalls near 1e-6 (moreau_solver_agreement_test shows their trajectories still agree).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/model/plank_box/plank_box_system.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

using model::PlankBoxParameters;
using model::PlankBoxSystem;

// Plank at its static equilibrium without the box (k φ = −m_P g (L_P/2) cos φ, by fixed point),
// box `drop` above the plank's surface at `along` from the hinge, turned by `tilt` from it.
Eigen::Vector4d drop_state(const PlankBoxParameters& p, double along, double drop, double tilt) {
  double phi = 0.0;
  for (int i = 0; i < 50; ++i)
    phi = -p.plank_mass * p.gravity * 0.5 * p.plank_length * std::cos(phi) / p.plank_stiffness;
  const Eigen::Vector2d e1(std::cos(phi), std::sin(phi)), e2(-std::sin(phi), std::cos(phi));
  // Lowest corner `drop` above the surface: half-height projected plus half-length for the tilt.
  const double lowest =
      0.5 * p.box_height * std::cos(tilt) + 0.5 * p.box_length * std::abs(std::sin(tilt));
  const Eigen::Vector2d centre = along * e1 + (0.5 * p.plank_thickness + lowest + drop) * e2;
  return {centre.x(), centre.y(), phi + tilt, phi};
}

struct Landing {
  RunSummary summary;
  double max_approach_speed = 0.0;
  int impact_steps = 0;
};

Landing land(double tilt, double dt) {
  PlankBoxParameters parameters;
  parameters.restitution = 0.3;
  const PlankBoxSystem<double> system(parameters);
  MoreauJeanOptions options;
  options.dt = dt;
  options.forces = ForceTreatment::kLinearlyImplicit;
  options.solver = "lemke";
  MoreauJeanStepper stepper(system, options);
  Landing landing;
  const auto result = stepper.simulate(
      drop_state(parameters, 0.6, 0.05, tilt), Eigen::Vector4d::Zero(),
      [](double) { return Eigen::VectorXd::Zero(3); }, 1.5,
      [&](const MoreauJeanState&, const StepReport& report) {
        bool impact = false;
        for (const auto& c : report.impulses()) {
          landing.max_approach_speed = std::max(landing.max_approach_speed, -c.u_before(0));
          impact = impact || (c.r_n > 0 && c.u_before(0) < -1e-3);
        }
        landing.impact_steps += impact ? 1 : 0;
      });
  EXPECT_TRUE(result.succeeded()) << to_string(result.status) << ": " << result.message
                                  << " at step " << result.summary.steps;
  landing.summary = result.summary;
  return landing;
}

TEST(MoreauPlankBox, FlatAndTiltedLandingsDissipateAndPenetrateLessThanHTimesSpeed) {
  for (double tilt : {0.0, 0.3}) {
    for (double dt : {2e-3, 1e-3}) {
      const Landing l = land(tilt, dt);
      std::printf(
          "plank-box tilt %.1f dt %.0e: impacts %d, max energy rise %.3e J, energy %.4f -> "
          "%.4f J, max penetration %.3e m, h * approach speed %.3e m\n",
          tilt, dt, l.impact_steps, l.summary.max_energy_rise, l.summary.energy_start,
          l.summary.energy_end, l.summary.max_penetration, dt * l.max_approach_speed);
      EXPECT_GT(l.impact_steps, 0);
      EXPECT_LE(l.summary.max_energy_rise, 1e-8) << tilt << " " << dt;
      EXPECT_LT(l.summary.energy_end, l.summary.energy_start);
      EXPECT_LE(l.summary.max_penetration, dt * l.max_approach_speed) << tilt << " " << dt;
    }
  }
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
