#include "lib/model/planar/planar_system_autodiff.hpp"

#include "lib/model/planar/planar_system_impl.hpp"

namespace impactbench::model::planar {

template class PlanarRigidBodySystem<AutoDiff>;

}  // namespace impactbench::model::planar
