#include "solvers/friction/friction_residual.hpp"

#include <cmath>

#include "solvers/friction/coulomb_cone.hpp"
#include "solvers/friction/delassus_access.hpp"

namespace impactbench::solvers {
namespace {

// A planar contact's terms (d = 2), added to `sum_of_squares`: the general loop below in
// scalars, the same operations in the same order, so the same bits, without its small vectors
// (a Moreau–Jean solve evaluates this for every contact at every residual check).
void add_planar_contact_terms(double mu, double r_n, double r_t, double u_n, double u_t,
                              double& sum_of_squares) {
  const double z_n = r_n - (u_n + mu * std::sqrt(u_t * u_t));
  const double z_t = r_t - u_t;
  // The tangent's norm as Eigen forms it, sqrt(z_t²).
  const ConeProjection projected = coulomb_cone_projection(mu, z_n, std::sqrt(z_t * z_t));
  const double difference_n = r_n - projected.normal;
  sum_of_squares += difference_n * difference_n;
  const double difference_t = r_t - (projected.apex ? 0.0 : projected.tangent_factor * z_t);
  sum_of_squares += difference_t * difference_t;
}

}  // namespace

double friction_residual(const FrictionProblem& problem, const Eigen::VectorXd& r,
                         const Eigen::VectorXd& u) {
  const int d = problem.dimension;
  double sum_of_squares = 0.0;
  if (d == 2) {
    for (int i = 0; i < problem.num_contacts(); ++i)
      add_planar_contact_terms(problem.mu(i), r(2 * i), r(2 * i + 1), u(2 * i), u(2 * i + 1),
                               sum_of_squares);
  } else {
    // Per contact with small vectors (d ≤ 3); the projection is coulomb_cone.hpp's three cases.
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
  }
  const double q_norm = problem.q.norm();
  return std::sqrt(sum_of_squares) / (q_norm > 0.0 ? q_norm : 1.0);
}

double friction_residual(const FrictionProblem& problem, const Eigen::VectorXd& r) {
  return friction_residual(problem, r, contact_velocity(problem, r));
}

}  // namespace impactbench::solvers
