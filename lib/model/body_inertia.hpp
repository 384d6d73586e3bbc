#pragma once
// The principal moments of inertia of a spatial body, shared by our systems and the adapters so
// that every engine gives a body the same inertia.
#include <string>

#include <Eigen/Core>

#include "lib/model/body_spec.hpp"

namespace impactbench::model {

/// BodySpec::inertia when given, else a uniform solid's: sphere 2/5 m r², cuboid
/// m/12 (b² + c², a² + c², a² + b²) for sides (a, b, c) [kg m²].
Eigen::Vector3d principal_inertia(const BodySpec& body);

/// Empty when `inertia` can be a rigid body's principal moments (finite, > 0, each at most the
/// sum of the other two); else what is wrong with it.
std::string inertia_problem(const Eigen::Vector3d& inertia);

}  // namespace impactbench::model
