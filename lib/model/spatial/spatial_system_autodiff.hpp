#pragma once
// The forward-mode autodiff scalar the sensitivity module uses, and the system instantiated
// for it (in spatial_system_autodiff.cpp).
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "lib/model/spatial/spatial_system.hpp"

namespace impactbench::model::spatial {

using AutoDiff = Eigen::AutoDiffScalar<Eigen::VectorXd>;
extern template class SpatialRigidBodySystem<AutoDiff>;

}  // namespace impactbench::model::spatial
