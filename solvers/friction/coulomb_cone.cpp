#include "solvers/friction/coulomb_cone.hpp"

#include <algorithm>

namespace impactbench::solvers {

LocalVector project_on_coulomb_cone(double mu, const LocalVector& x) {
  const double normal = x(0);
  const auto tangent = x.tail(x.size() - 1);
  const double slip = tangent.norm();
  if (normal >= 0.0 && slip <= mu * normal) return x;
  if (mu * slip <= -normal) return LocalVector::Zero(x.size());
  // Case (3): s > 0 here, since s = 0 falls in case (1) or (2).
  const double t = (normal + mu * slip) / (1.0 + mu * mu);
  LocalVector projected(x.size());
  projected(0) = t;
  projected.tail(x.size() - 1) = (mu * t / slip) * tangent;
  return projected;
}

LocalVector project_on_disk(double radius, const LocalVector& x_t) {
  const double length = x_t.norm();
  if (length <= radius) return x_t;
  if (radius <= 0.0 || length == 0.0) return LocalVector::Zero(x_t.size());
  return (radius / length) * x_t;
}

}  // namespace impactbench::solvers
