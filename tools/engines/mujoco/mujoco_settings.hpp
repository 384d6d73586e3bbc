#pragma once
// MuJoCo's settings (tools/engines/mujoco/mujoco_engine.cpp runs them) as plain data with their
// schema, here so that the scenario loader and the command line check them without MuJoCo
// itself. --dt and the scenario's dt set timestep, --tol sets tolerance, --solver sets solver.
#include <optional>

#include "lib/engines/impact_criteria.hpp"
#include "lib/engines/settings/engine_settings.hpp"

namespace impactbench::engines {

enum class MujocoIntegrator { kEuler, kRk4, kImplicit };
enum class MujocoSolver { kPgs, kCg, kNewton };
enum class MujocoCone { kPyramidal, kElliptic };

/// The settings that decide MuJoCo's fidelity. MuJoCo's contacts are soft: a contact's
/// constraint-space acceleration is driven towards a_ref = −b ζ_n − k h, mixed with the
/// unconstrained motion by the impedance d(h) ∈ [d_min, d_max] (solimp). The adapter passes
/// solref in MuJoCo's direct form (−k, −b) with k = 1/τ² and b = 2ζ/τ: a spring–damper of
/// natural frequency 1/τ and damping ratio ζ whatever ζ is. Such an oscillator leaves a contact
/// with restitution e = exp(−ζπ/√(1 − ζ²)), so ζ = −ln e/√(π² + ln² e) (1 for e = 0) unless
/// solref_dampratio is given.
struct MujocoSettings {
  double timestep = 1e-3;  ///< [s] (the scenario's dt unless given)
  MujocoIntegrator integrator = MujocoIntegrator::kEuler;
  MujocoSolver solver = MujocoSolver::kNewton;
  int iterations = 100;      ///< main solver iterations (MuJoCo default 100)
  double tolerance = 1e-10;  ///< main solver tolerance (MuJoCo default 1e-8)
  MujocoCone cone = MujocoCone::kElliptic;
  double impratio = 1.0;      ///< friction-to-normal impedance ratio (MuJoCo default 1)
  int noslip_iterations = 0;  ///< noslip post-solver iterations (MuJoCo default 0)
  /// τ [s], the contact's time scale 1/ω; unset: max(5 ms, 2 timesteps)
  std::optional<double> solref_timeconst;
  std::optional<double> solref_dampratio;  ///< ζ; unset: from the restitution e (above)
  /// d at zero penetration (MuJoCo default 0.9). Near-rigid but not more: with d_max = 0.999
  /// the Newton solver on the elliptic cone threw the plank–box's box off the plank.
  double solimp_dmin = 0.99;
  double solimp_dmax = 0.99;   ///< d at penetration ≥ width (MuJoCo default 0.95)
  double solimp_width = 1e-3;  ///< [m] (MuJoCo default 0.001)
  ImpactCriteria impact;       ///< when a closing contact is reported as an impact event
};

/// The time constant in force: the setting, else max(5 ms, 2 timesteps).
double solref_timeconst(const MujocoSettings& settings);

/// ζ(e) = −ln e/√(π² + ln² e), 1 for e = 0: the damping ratio of a linear spring–damper whose
/// contact ends with separation speed e times the approach speed.
double restitution_damping_ratio(double restitution);

const SettingsSchema<MujocoSettings>& mujoco_settings_schema();
const EngineSettings& mujoco_settings();

}  // namespace impactbench::engines
