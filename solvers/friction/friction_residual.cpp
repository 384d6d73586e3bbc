#include "solvers/friction/friction_residual.hpp"

#include <cmath>

#include "solvers/friction/coulomb_cone.hpp"
#include "solvers/friction/delassus_access.hpp"

namespace impactbench::solvers {

double friction_residual(const FrictionProblem& problem, const Eigen::VectorXd& r,
                         const Eigen::VectorXd& u) {
  const int d = problem.dimension;
  double sum_of_squares = 0.0;
  // Scalar per-contact code (d ≤ 3); the projection is the three cases of coulomb_cone.hpp.
  for (int i = 0; i < problem.num_contacts(); ++i) {
    const double mu = problem.mu(i);
    const int first = i * d;
    double u_t_squared = 0.0;
    for (int k = 1; k < d; ++k) u_t_squared += u(first + k) * u(first + k);
    LocalVector z(d);  // r − (u + g(u))
    z(0) = r(first) - (u(first) + mu * std::sqrt(u_t_squared));
    for (int k = 1; k < d; ++k) z(k) = r(first + k) - u(first + k);
    const LocalVector projected = project_on_coulomb_cone(mu, z);
    for (int k = 0; k < d; ++k) {
      const double difference = r(first + k) - projected(k);
      sum_of_squares += difference * difference;
    }
  }
  const double q_norm = problem.q.norm();
  return std::sqrt(sum_of_squares) / (q_norm > 0.0 ? q_norm : 1.0);
}

double friction_residual(const FrictionProblem& problem, const Eigen::VectorXd& r) {
  return friction_residual(problem, r, contact_velocity(problem, r));
}

}  // namespace impactbench::solvers
