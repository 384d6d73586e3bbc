#include "solvers/friction/coulomb_cone.hpp"

#include <algorithm>

namespace impactbench::solvers {

LocalVector project_on_coulomb_cone(double mu, const LocalVector& x) {
  const auto tangent = x.tail(x.size() - 1);
  const ConeProjection p = coulomb_cone_projection(mu, x(0), tangent.norm());
  if (p.apex) return LocalVector::Zero(x.size());
  LocalVector projected(x.size());
  projected(0) = p.normal;
  projected.tail(x.size() - 1) = p.tangent_factor * tangent;
  return projected;
}

LocalVector project_on_disk(double radius, const LocalVector& x_t) {
  const double length = x_t.norm();
  if (length <= radius) return x_t;
  if (radius <= 0.0 || length == 0.0) return LocalVector::Zero(x_t.size());
  return (radius / length) * x_t;
}

}  // namespace impactbench::solvers
