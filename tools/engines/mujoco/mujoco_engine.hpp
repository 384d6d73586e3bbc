#pragma once
// MuJoCo 2.2.2 (Debian libmujoco-dev, plain -lmujoco) as a reference engine. The model is MJCF
// text built in memory from the scene and loaded through a virtual file system: planar free
// bodies move on two slide joints (world x, y) and a hinge about z; spatial ones on a free
// joint; the plank–box's plank on a hinge with MuJoCo's native joint stiffness and damping.
//
// Mapping: every geom gets the scenario's μ as sliding friction (torsional and rolling
// friction 0, condim 3); MuJoCo combines the pair's friction by maximum, so the pair gets μ.
// Restitution has no MuJoCo parameter: contacts are soft, and the damping ratio of solref is
// derived from e (tools/engines/mujoco/mujoco_settings.hpp). Boundaries are MuJoCo planes
// (exact half-spaces). A planar disk is a sphere with the disk's inertia m r²/2; a planar box a
// cuboid of depth max(w, h).
#include "lib/engines/run_result.hpp"
#include "tools/engines/fixed_step/reference_scene.hpp"
#include "tools/engines/mujoco/mujoco_settings.hpp"

namespace impactbench::adapters {

using engines::MujocoSettings;

/// Runs the scene in MuJoCo with fixed steps of settings.timestep (scene.dt is the same).
engines::RunResult run_mujoco(const ReferenceScene& scene, const MujocoSettings& settings = {},
                              const engines::RecordingOptions& recording = {});

}  // namespace impactbench::adapters
