#pragma once
// The spatial system on the models' autodiff scalar (lib/model/autodiff.hpp), instantiated once
// in spatial_system_autodiff.cpp for the sensitivity module and tests.
#include "lib/model/autodiff.hpp"
#include "lib/model/spatial/spatial_system.hpp"

namespace impactbench::model::spatial {

extern template class SpatialRigidBodySystem<AutoDiff>;

}  // namespace impactbench::model::spatial
