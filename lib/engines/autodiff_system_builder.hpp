#pragma once
// The scenario's system of system_builder.hpp on forward-mode AD scalars, for the Jacobians of
// the sensitivity module. Kept apart so that the AD headers stay out of the engines' includes.
#include <memory>

#include "lib/model/autodiff.hpp"
#include "lib/model/lagrangian_system.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::engines {

/// The same bodies, planes, material and inputs as build_system(scenario).system.
std::unique_ptr<const model::LagrangianSystem<model::AutoDiff>> build_autodiff_system(
    const scenario::Scenario& scenario);

}  // namespace impactbench::engines
