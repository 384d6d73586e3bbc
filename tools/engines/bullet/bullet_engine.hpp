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
#include "lib/engines/contact_events.hpp"
#include "lib/engines/run_result.hpp"
#include "tools/engines/bullet/bullet_settings.hpp"
#include "tools/engines/fixed_step/reference_scene.hpp"

namespace impactbench::adapters {

using engines::BulletSettings;
using engines::BulletSolver;

/// Runs the scene in a Bullet world with fixed steps of scene.dt.
/// Records as `recording` asks (the library's default keeps everything in memory).
engines::RunResult run_bullet(const ReferenceScene& scene, const BulletSettings& settings = {},
                              const engines::RecordingOptions& recording = {});

}  // namespace impactbench::adapters
