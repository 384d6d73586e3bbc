#pragma once
// From a scenario to our model of it: the Lagrangian system (planar or spatial rigid bodies, or
// the plank–box) and its initial state. Every engine of ours, the reference engines' energy
// column, the sensitivity command and the tests use this one construction
// (autodiff_system_builder.hpp gives the same system on AD scalars).
#include <memory>

#include <Eigen/Core>

#include "lib/model/lagrangian_system.hpp"
#include "lib/model/spatial/spatial_system_spec.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::engines {

struct BuiltSystem {
  std::unique_ptr<const model::LagrangianSystem<double>> system;
  Eigen::VectorXd q0;  ///< initial positions
  Eigen::VectorXd v0;  ///< initial velocities
};

/// Throws std::invalid_argument (naming the body and field) for specs the model rejects.
BuiltSystem build_system(const scenario::Scenario& scenario);

/// The spec build_system builds a spatial rigid-body scenario's system from (its bodies,
/// planes, material, gravity and inputs).
model::spatial::SpatialSystemSpec spatial_spec(const scenario::Scenario& scenario);

}  // namespace impactbench::engines
