#pragma once
// Siconos 4.4 (Debian libsiconos-kernel-dev) as a reference engine, built only where the kernel
// is installed (tools/cmake/find_siconos_kernel.cmake). Its Moreau–Jean scheme runs our own
// model of a scenario (siconos_system_engine.hpp); this file runs its event-driven scheme on the
// reference scene.
//
// Event-driven (scheme = event_driven): planar scenes of one disk or box, a
// LagrangianLinearTIDS in (x, y, θ) with its weight as a constant external force, against the
// scene's half-spaces. Each contact (a disk with a plane; each corner of a box with a plane) is
// an Interaction with a NewtonImpactNSL (the scenario's e) and a LagrangianLinearTIR of one row,
// the normal gap linear in q: exact for a disk, for a box corner the relation at the box's
// initial angle, so a box must not turn: the run stops with an error once one has turned by
// more than 1e-6 rad. Friction and force inputs are refused (Siconos' EventDriven states
// frictionless contacts); so are hinges, several bodies and spatial scenes.
#include "lib/engines/run_result.hpp"
#include "tools/engines/fixed_step/reference_scene.hpp"
#include "tools/engines/siconos/siconos_settings.hpp"

namespace impactbench::adapters {

using engines::SiconosSettings;

/// Runs the scene with Siconos' EventDriven and a time discretisation of scene.dt; throws
/// UnsupportedScene for what it does not state (scheme moreau_jean included: see above).
engines::RunResult run_siconos(const ReferenceScene& scene, const SiconosSettings& settings = {},
                               const engines::RecordingOptions& recording = {});

}  // namespace impactbench::adapters
