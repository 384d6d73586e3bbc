#pragma once
// The planar system on forward-mode automatic differentiation scalars (dynamic derivative
// size), instantiated once in planar_system_autodiff.cpp for the sensitivity module and tests.
#include "lib/model/autodiff.hpp"
#include "lib/model/planar/planar_system.hpp"

namespace impactbench::model::planar {

extern template class PlanarRigidBodySystem<AutoDiff>;
using PlanarRigidBodySystemAd = PlanarRigidBodySystem<AutoDiff>;

}  // namespace impactbench::model::planar
