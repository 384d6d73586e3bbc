#pragma once
// ODE 0.16 (Debian libode-dev, double precision, pkg-config ode) as a reference engine: spatial
// scenarios with free bodies, planar ones with every free body held in the x–y plane by a
// Plane2D joint, hinged bodies (the plank–box) by a hinge joint about z to the world with the
// spring–damper torque −k φ − b φ̇ applied at the start of each step.
//
// Mapping: ODE has no materials; the adapter gives every contact the scenario's μ and e (the
// combine rule is ours: one material per scenario). Restitution through ODE's bounce (a target
// separation speed e·approach, above bounce_velocity); friction by dContactApprox1 (μ·λ_n per
// friction direction; the first direction in the plane of a planar scene) or ODE's default box
// of constant force limits. Boundaries are ODE's exact half-spaces (dCreatePlane). A planar
// disk is a sphere with the disk's inertia m r²/2; a planar box a cuboid of depth max(w, h).
#include "lib/engines/run_result.hpp"
#include "tools/engines/fixed_step/reference_scene.hpp"
#include "tools/engines/ode/ode_settings.hpp"

namespace impactbench::adapters {

using engines::OdeSettings;

/// Runs the scene in an ODE world with fixed steps of scene.dt.
engines::RunResult run_ode(const ReferenceScene& scene, const OdeSettings& settings = {},
                           const engines::RecordingOptions& recording = {});

}  // namespace impactbench::adapters
