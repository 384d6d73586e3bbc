// The two treatments of the smooth forces (free_motion.hpp) on a mass on a vertical spring and
// damper above a floor. Linearly implicit with θ = 1/2 is the trapezoidal rule on the smooth
// part: for linear forces it conserves the energy of a free undamped oscillation exactly and
// never raises it across a step when damping, impacts (e < 1) and the solver act; explicit
// forces give the Störmer–Verlet step, whose energy oscillates by O(h²).
#include <cmath>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

constexpr double kMass = 1.0, kStiffness = 400.0, kGravity = 9.81;

MoreauJeanOptions options_with(ForceTreatment forces, double dt = 1e-3) {
  MoreauJeanOptions o;
  o.dt = dt;
  o.forces = forces;
  o.record_impulses = false;
  return o;
}

TEST(MoreauForceTreatment, LinearlyImplicitConservesFreeOscillationEnergy) {
  // Rest height 1 m, released 0.1 m above equilibrium: never reaches the floor.
  const test_support::SpringMassFloorTestSystem system(kMass, kStiffness, 0.0, 1.0, kGravity, 0.0);
  MoreauJeanStepper stepper(system, options_with(ForceTreatment::kLinearlyImplicit));
  const Eigen::Vector2d q0(0.0, 1.0 - kMass * kGravity / kStiffness + 0.1);
  const auto result = stepper.simulate(q0, Eigen::Vector2d::Zero(), {}, 2.0);
  ASSERT_TRUE(result.succeeded());
  EXPECT_NEAR(result.summary.energy_end, result.summary.energy_start,
              1e-9 * std::abs(result.summary.energy_start));
  // Second order in phase: after 2 s the position matches the exact oscillation to O(h²).
  const double omega = std::sqrt(kStiffness / kMass);
  const double exact = 1.0 - kMass * kGravity / kStiffness + 0.1 * std::cos(omega * 2.0);
  EXPECT_NEAR(result.final_state.q(1), exact, 0.1 * std::pow(omega * 1e-3, 2) * omega * 2.0);

  MoreauJeanStepper explicit_stepper(system, options_with(ForceTreatment::kExplicit));
  const auto verlet = explicit_stepper.simulate(q0, Eigen::Vector2d::Zero(), {}, 2.0);
  std::printf("free oscillation energy drift: implicit %.3e, explicit max rise %.3e J/step\n",
              result.summary.energy_end - result.summary.energy_start,
              verlet.summary.max_energy_rise);
  EXPECT_GT(verlet.summary.max_energy_rise, 1e-9);  // the Verlet step's energy oscillates
}

TEST(MoreauForceTreatment, LinearlyImplicitEnergyNeverRisesWithImpactsAndDamping) {
  // Rest height 0.5 m, dropped from 1 m: hits the floor repeatedly (e = 0.5), damped.
  const test_support::SpringMassFloorTestSystem system(kMass, kStiffness, 0.5, 0.5, kGravity, 0.5);
  for (double dt : {1e-3, 1e-2}) {
    MoreauJeanStepper stepper(system, options_with(ForceTreatment::kLinearlyImplicit, dt));
    const auto result =
        stepper.simulate(Eigen::Vector2d(0.0, 1.0), Eigen::Vector2d::Zero(), {}, 3.0);
    ASSERT_TRUE(result.succeeded());
    std::printf("spring+floor dt %.0e: max energy rise %.3e J, energy %.4f -> %.4f J\n", dt,
                result.summary.max_energy_rise, result.summary.energy_start,
                result.summary.energy_end);
    EXPECT_LE(result.summary.max_energy_rise, 1e-9) << dt;
    EXPECT_GT(result.summary.max_active_contacts, 0) << "the mass must reach the floor";
  }
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
