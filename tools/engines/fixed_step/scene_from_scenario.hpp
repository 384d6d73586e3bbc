#pragma once
#include "lib/scenario/scenario.hpp"
#include "tools/engines/fixed_step/reference_scene.hpp"

namespace impactbench::adapters {

/// The reference engines' view of a scenario: free rigid bodies, or the plank–box as a free box
/// and a plank hinged to the world with its spring and damper.
/// `duration` and `dt` are the run's, in force (engines::resolve_run_options).
ReferenceScene make_reference_scene(const scenario::Scenario& scenario, double duration, double dt);

}  // namespace impactbench::adapters
