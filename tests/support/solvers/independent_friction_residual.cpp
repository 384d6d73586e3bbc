#include "tests/support/solvers/independent_friction_residual.hpp"

#include <cmath>
#include <limits>

namespace impactbench::test_support {
namespace {

/// Π_K(z) for K = {(n, t) : ‖t‖ ≤ μ n}. In the half-plane spanned by e_n and t/‖t‖, with
/// coordinates (n, s = ‖t‖), K is the wedge between the n axis and the ray b = (1, μ)/√(1+μ²),
/// and its polar cone the wedge beyond the normal to b. Points in K stay, points in the polar
/// cone go to 0, the rest go to their orthogonal foot (z·b) b on the ray.
Eigen::VectorXd project_on_cone(double mu, const Eigen::VectorXd& z) {
  const double n = z(0);
  const Eigen::VectorXd t = z.tail(z.size() - 1);
  const double s = t.norm();
  if (n >= 0.0 && s <= mu * n) return z;
  if (mu * s <= -n) return Eigen::VectorXd::Zero(z.size());
  const double scale = 1.0 / std::sqrt(1.0 + mu * mu);
  const double foot = (n + mu * s) * scale;  // z·b in the (n, s) plane
  Eigen::VectorXd p(z.size());
  p(0) = foot * scale;
  p.tail(z.size() - 1) = (foot * mu * scale / s) * t;  // s = 0 fell in a case above
  return p;
}

Eigen::VectorXd contact_velocity(const solvers::FrictionProblem& problem,
                                 const Eigen::VectorXd& r) {
  return (problem.is_sparse ? Eigen::VectorXd(problem.sparse_W * r)
                            : Eigen::VectorXd(problem.dense_W * r)) +
         problem.q;
}

double q_scale(const solvers::FrictionProblem& problem) {
  const double q_norm = problem.q.norm();
  return q_norm > 0.0 ? q_norm : 1.0;
}

}  // namespace

double independent_friction_residual(const solvers::FrictionProblem& problem,
                                     const Eigen::VectorXd& r) {
  const Eigen::VectorXd u = contact_velocity(problem, r);
  const int d = problem.dimension;
  double sum_of_squares = 0.0;
  for (int i = 0; i < problem.num_contacts(); ++i) {
    const Eigen::VectorXd ri = r.segment(i * d, d), ui = u.segment(i * d, d);
    Eigen::VectorXd z = ri - ui;
    z(0) -= problem.mu(i) * ui.tail(d - 1).norm();
    sum_of_squares += (ri - project_on_cone(problem.mu(i), z)).squaredNorm();
  }
  return std::sqrt(sum_of_squares) / q_scale(problem);
}

double residual_allowance_for_velocity(const solvers::FrictionProblem& problem,
                                       const Eigen::VectorXd& r, const Eigen::VectorXd& u) {
  const double mu_max = problem.mu.size() > 0 ? problem.mu.maxCoeff() : 0.0;
  // Round-off: each component of r − Π(r − u − g) carries a few ulps of |r_i| + (|W| |r|)_i +
  // |q_i| (the product W r summed in another order); 16 ulps covers the sums of d ≤ 3 terms.
  const Eigen::VectorXd magnitude =
      r.cwiseAbs() + problem.q.cwiseAbs() +
      (problem.is_sparse ? Eigen::VectorXd(problem.sparse_W.cwiseAbs() * r.cwiseAbs())
                         : Eigen::VectorXd(problem.dense_W.cwiseAbs() * r.cwiseAbs()));
  const double round_off = 16 * std::numeric_limits<double>::epsilon() * magnitude.norm();
  return ((1.0 + mu_max) * (u - contact_velocity(problem, r)).norm() + round_off) /
         q_scale(problem);
}

}  // namespace impactbench::test_support
