#pragma once
// Bullet 3.24 (Debian libbullet-dev, double precision through pkg-config bullet-float64) as a
// reference engine for spatial scenarios, and for planar ones with the bodies held in the x–y
// plane by linear factor (1, 1, 0) and angular factor (0, 0, 1).
//
// Faithful mapping: Bullet combines friction and restitution by product, so the static
// boundaries get 1 and every body the scenario's μ and e. A planar disk is a sphere whose
// inertia about z is set to the disk's m r²/2; a planar box a cuboid of depth max(w, h).
// Boundaries are large boxes (btStaticPlaneShape is less faithful). Steps are fixed:
// stepSimulation(dt, 0) — no internal sub-stepping or interpolation.
#include <string>

#include "lib/engines/contact_events.hpp"
#include "lib/engines/run_result.hpp"
#include "tools/adapters/reference_scene.hpp"

namespace impactbench::adapters {

enum class BulletSolver {
  kSequentialImpulse,  ///< btSequentialImpulseConstraintSolver (Bullet's default)
  kMlcpDantzig,        ///< btMLCPSolver with btDantzigSolver (direct LCP per step; slow)
};

/// The settings that decide Bullet's fidelity; defaults chosen for accuracy on the shipped
/// scenarios (50 iterations converge friction on a box's 4 contacts; thin margins keep corners
/// sharp).
struct BulletSettings {
  BulletSolver solver = BulletSolver::kSequentialImpulse;
  int solver_iterations = 50;                ///< Bullet default 10
  double restitution_threshold = 1e-3;       ///< [m/s] below: no bounce (Bullet default 0.2)
  bool split_impulse = true;                 ///< position correction without adding momentum
  double split_impulse_depth = 0.0;          ///< [m] split impulse beyond this depth (Bullet 0.04)
  double erp = 0.2;                          ///< contact error reduction (m_erp2)
  double collision_margin = 1e-3;            ///< [m] convex margin of boxes (Bullet default 0.04)
  double contact_breaking_threshold = 2e-3;  ///< [m] gContactBreakingThreshold (default 0.02)
  engines::ImpactCriteria impact;            ///< when a closing contact pair is an impact
};

BulletSolver parse_bullet_solver(const std::string& name);  ///< "si" | "mlcp-dantzig"

/// Runs the scene in a Bullet world with fixed steps of scene.dt.
engines::RunResult run_bullet(const ReferenceScene& scene, const BulletSettings& settings = {});

}  // namespace impactbench::adapters
