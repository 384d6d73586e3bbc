#pragma once
// Siconos' settings (tools/engines/siconos/siconos_engine.cpp runs them; built only where the
// Siconos kernel is installed) as plain data with their schema, here so that the scenario loader
// and the command line check them in every build. --dt and the scenario's dt set dt, --tol sets
// tolerance, --solver sets solver.
#include "lib/engines/impact_criteria.hpp"
#include "lib/engines/settings/engine_settings.hpp"

namespace impactbench::engines {

/// Siconos Numerics' planar friction-contact solvers (fc2d), by their Siconos names.
enum class SiconosSolver {
  kNsgs,   ///< SICONOS_FRICTION_2D_NSGS: nonsmooth Gauss–Seidel over the contacts
  kLemke,  ///< SICONOS_FRICTION_2D_LEMKE: the problem as an LCP, Lemke's pivoting
  kEnum,   ///< SICONOS_FRICTION_2D_ENUM: enumeration of the complementarity cases
  kCpg,    ///< SICONOS_FRICTION_2D_CPG: conjugate projected gradient
};

/// Siconos' simulation schemes.
enum class SiconosScheme {
  kMoreauJean,   ///< MoreauJeanOSI + TimeStepping + FrictionContact (fixed steps)
  kEventDriven,  ///< LsodarOSI + EventDriven, impact and acceleration LCPs (frictionless only)
};

/// Siconos' MoreauJeanOSI + TimeStepping + FrictionContact, with the settings that make it the
/// same scheme as our Moreau–Jean (moreau_jean_stepper.hpp) where the two are given the same
/// values: θ of the θ-method, and Siconos' activation rule "active when
/// y_k + γ h ẏ_k ≤ activation_threshold" (MoreauJeanOSI's gamma and
/// constraintActivationThreshold; our activation_horizon and activation_tolerance).
/// The event-driven scheme takes `dt` as its time discretisation (an event, and a sample, every
/// dt) and integrates between events with Lsodar to `rtol` and `atol`.
struct SiconosSettings {
  SiconosScheme scheme = SiconosScheme::kMoreauJean;
  double dt = 1e-3;    ///< fixed step h [s] (the scenario's unless given)
  double theta = 0.5;  ///< θ of the θ-method, in [0.5, 1]
  double gamma = 0.5;  ///< γ of the activation forecast, in [0, 1] (Siconos' default 1/2)
  /// [m], >= 0. Siconos' own default is 0; 1e-9 here, as our activation_tolerance: a body
  /// placed exactly on a plane ends its first step with a gap of round-off size (1e-14 m) and
  /// with 0 would leave the contact set for a step and fall by g h²/2.
  double activation_threshold = 1e-9;
  SiconosSolver solver = SiconosSolver::kNsgs;
  double tolerance = 1e-10;   ///< the solver's tolerance (Siconos' own error measure)
  int max_iterations = 1000;  ///< the solver's iteration limit
  double rtol = 1e-12;        ///< event_driven: Lsodar's relative tolerance
  double atol = 1e-14;        ///< event_driven: Lsodar's absolute tolerance [m, m/s, rad, rad/s]
  /// event_driven: Siconos' _TOL_ED [m]: a contact with |gap| below it is closed, and a gap
  /// below −event_tolerance stops the run. Siconos' default 1e4 ε ≈ 2.2e-12 m.
  double event_tolerance = 1e4 * 2.220446049250313e-16;
  ImpactCriteria impact;  ///< when a closing contact is reported as an impact event
};

const SettingsSchema<SiconosSettings>& siconos_settings_schema();
const EngineSettings& siconos_settings();

}  // namespace impactbench::engines
