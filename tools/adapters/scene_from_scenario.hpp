#pragma once
#include "lib/scenario/scenario.hpp"
#include "tools/adapters/engine_registry.hpp"
#include "tools/adapters/reference_scene.hpp"

namespace impactbench::adapters {

/// The reference engines' view of a scenario. Throws UnsupportedScene for systems that are not
/// free rigid bodies (the plank–box's spring-loaded hinge has no counterpart in the adapters).
ReferenceScene make_reference_scene(const scenario::Scenario& scenario, const RunOptions& options);

}  // namespace impactbench::adapters
