#include "lib/model/spatial/spatial_system_autodiff.hpp"

#include "lib/model/spatial/spatial_system_impl.hpp"

namespace impactbench::model::spatial {
template class SpatialRigidBodySystem<AutoDiff>;
}  // namespace impactbench::model::spatial
