#pragma once
// ODE's settings (tools/engines/ode/ode_engine.cpp runs them) as plain data with their schema, here
// so that the scenario loader and the command line check them without ODE itself. --dt and the
// scenario's dt set dt, --solver sets stepper; ODE has no tolerance.
#include "lib/engines/impact_criteria.hpp"
#include "lib/engines/settings/engine_settings.hpp"

namespace impactbench::engines {

enum class OdeStepper {
  kExact,  ///< dWorldStep: the step's LCP solved by a pivoting (Dantzig) method
  kQuick,  ///< dWorldQuickStep: a fixed number of projected Gauss–Seidel sweeps
};

enum class OdeFriction {
  /// dContactApprox1: each of the two friction directions limited by μ·λ_n (a pyramid, exact
  /// Coulomb in the plane)
  kPyramid,
  /// ODE's default: each friction direction limited by a constant force, set to μ times the
  /// weight share of the contact (μ m g / contact points of the pair); exact only where the
  /// normal force is that weight (flat ground, no impact)
  kBox,
};

/// The settings that decide ODE's fidelity; defaults chosen for accuracy on the shipped
/// scenarios (exact LCP, near-rigid contacts).
struct OdeSettings {
  double dt = 1e-3;  ///< fixed step [s] (the scenario's unless given)
  OdeStepper stepper = OdeStepper::kExact;
  int quick_iterations = 50;  ///< sweeps of dWorldQuickStep (ODE default 20)
  OdeFriction friction = OdeFriction::kPyramid;
  double erp = 0.2;               ///< error reduction of contacts and joints (ODE default 0.2)
  double cfm = 1e-9;              ///< constraint force mixing [m/N·s] (ODE double default 1e-10)
  double bounce_velocity = 1e-3;  ///< [m/s] bounce_vel: slower approaches do not bounce
  /// Contact points kept per pair of geometries: 4 hold a face on a face; the exact step's
  /// cost grows with the cube of all contact rows.
  int max_contacts = 4;
  ImpactCriteria impact;  ///< when a closing contact is reported as an impact event
};

const SettingsSchema<OdeSettings>& ode_settings_schema();
const EngineSettings& ode_settings();

}  // namespace impactbench::engines
