// The double instantiation; the autodiff one lives in spatial_system_autodiff.cpp.
#include "lib/model/spatial/spatial_system_impl.hpp"

namespace impactbench::model::spatial {
template class SpatialRigidBodySystem<double>;
}  // namespace impactbench::model::spatial
