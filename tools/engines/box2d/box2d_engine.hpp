#pragma once
// Box2D 2.4.1 (Debian libbox2d-dev) as a reference engine for planar scenarios.
//
// Faithful mapping: friction combines as sqrt(μ_a μ_b) and restitution as max(e_a, e_b) in
// Box2D, so every fixture, the static boundaries included, gets the scenario's μ and e (giving μ
// and e for every pair). Unavoidable deviations (documented in docs/reference-engines.md): Box2D
// computes in float; polygons carry a skin b2_polygonRadius = 2 b2_linearSlop = 1 cm compiled into
// the library, so a box rests about 1.5 cm and a disk on a box-shaped ground 1 cm above the exact
// height; restitution acts only above a velocity threshold.
#include "lib/engines/contact_events.hpp"
#include "lib/engines/run_result.hpp"
#include "tools/engines/box2d/box2d_settings.hpp"
#include "tools/engines/fixed_step/reference_scene.hpp"

namespace impactbench::adapters {

using engines::Box2dSettings;

/// Runs the scene in a Box2D world with fixed steps of scene.dt. Throws UnsupportedScene for a
/// spatial scene and std::invalid_argument for bad settings.
/// Records as `recording` asks (the library's default keeps everything in memory).
engines::RunResult run_box2d(const ReferenceScene& scene, const Box2dSettings& settings = {},
                             const engines::RecordingOptions& recording = {});

}  // namespace impactbench::adapters
