#pragma once
// Bullet's settings (tools/engines/bullet/bullet_engine.cpp runs them) as plain data with their
// schema, here so that the scenario loader and the command line check them without Bullet
// itself. --dt and the scenario's dt set dt, --solver sets solver; Bullet has no tolerance.
#include "lib/engines/impact_criteria.hpp"
#include "lib/engines/settings/engine_settings.hpp"

namespace impactbench::engines {

enum class BulletSolver {
  kSequentialImpulse,  ///< btSequentialImpulseConstraintSolver (Bullet's default)
  kMlcpDantzig,        ///< btMLCPSolver with btDantzigSolver (direct LCP per step; slow)
};

/// The settings that decide Bullet's fidelity; defaults chosen for accuracy on the shipped
/// scenarios (50 iterations converge friction on a box's 4 contacts; thin margins keep corners
/// sharp).
struct BulletSettings {
  double dt = 1e-3;  ///< fixed step [s] (the scenario's unless given)
  BulletSolver solver = BulletSolver::kSequentialImpulse;
  int solver_iterations = 50;           ///< Bullet default 10
  double restitution_threshold = 1e-3;  ///< [m/s] below: no bounce (Bullet default 0.2)
  bool split_impulse = true;            ///< position correction without adding momentum
  double split_impulse_depth = 0.0;     ///< [m] split impulse beyond this depth (Bullet 0.04)
  double erp = 0.2;                     ///< contact error reduction (m_erp2)
  /// [m] convex margin of boxes (Bullet default 0.04); fixed, not a setting: the box–box and
  /// sphere–box algorithms use the exact box, so it shows in no contact of our scenes.
  double collision_margin = 1e-3;
  double contact_breaking_threshold = 2e-3;  ///< [m] gContactBreakingThreshold (default 0.02)
  ImpactCriteria impact;  ///< when a closing contact is reported as an impact event
};

const SettingsSchema<BulletSettings>& bullet_settings_schema();
const EngineSettings& bullet_settings();

}  // namespace impactbench::engines
