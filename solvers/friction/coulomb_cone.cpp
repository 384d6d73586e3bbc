#include "solvers/friction/coulomb_cone.hpp"

namespace impactbench::solvers {

LocalVector project_on_coulomb_cone(double mu, const LocalVector& x) {
  return project_on_coulomb_cone_of(mu, x);
}

LocalVector project_on_disk(double radius, const LocalVector& x_t) {
  return project_on_disk_of(radius, x_t);
}

}  // namespace impactbench::solvers
