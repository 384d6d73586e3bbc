#pragma once
#include "lib/scenario/scenario.hpp"
#include "tools/adapters/reference_scene.hpp"

namespace impactbench::adapters {

/// The reference engines' view of a scenario. Throws UnsupportedScene for systems that are not
/// free rigid bodies (the plank–box's spring-loaded hinge has no counterpart in the adapters).
/// `duration` and `dt` are the run's, in force (engines::resolve_run_options).
ReferenceScene make_reference_scene(const scenario::Scenario& scenario, double duration, double dt);

}  // namespace impactbench::adapters
