#include "lib/model/planar/planar_system_impl.hpp"

namespace impactbench::model::planar {

template class PlanarRigidBodySystem<double>;

}  // namespace impactbench::model::planar
