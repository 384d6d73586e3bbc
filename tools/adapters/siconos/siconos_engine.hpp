#pragma once
// Siconos 4.4 (Debian libsiconos-kernel-dev) as a reference engine, built only where the kernel
// is installed (tools/cmake/find_siconos.cmake): its MoreauJeanOSI time-stepping with a planar
// FrictionContact problem solved by Siconos Numerics' fc2d solvers.
//
// What it states: planar scenes of disks and boxes, each a LagrangianLinearTIDS in (x, y, θ)
// with its weight as a constant external force, against the scene's half-spaces. Each contact
// (a disk with a plane; each corner of a box with a plane) is an Interaction with a
// NewtonImpactFrictionNSL (the scenario's e and μ, no tangential restitution) and a
// LagrangianLinearTIR: normal gap and tangential displacement linear in q. For a disk against a
// plane that relation is exact; for a box corner it is the relation at the box's initial angle,
// so a box must not turn: the run stops with an error once one has turned by more than 1e-6 rad.
// Force inputs are held over each step at their value at t_k + θh. Hinges, body–body contacts
// and spatial scenes are refused as unsupported.
#include "lib/engines/reference/siconos_settings.hpp"
#include "lib/engines/run_result.hpp"
#include "tools/adapters/reference_scene.hpp"

namespace impactbench::adapters {

using engines::SiconosSettings;

/// Runs the scene with Siconos' MoreauJeanOSI in fixed steps of scene.dt.
engines::RunResult run_siconos(const ReferenceScene& scene, const SiconosSettings& settings = {},
                               const engines::RecordingOptions& recording = {});

}  // namespace impactbench::adapters
