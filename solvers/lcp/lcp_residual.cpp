#include "solvers/lcp/lcp_residual.hpp"

#include <cmath>
#include <limits>

namespace impactbench::solvers::lcp {

Eigen::VectorXd lcp_velocity(const LcpProblem& problem, const Eigen::VectorXd& z) {
  Eigen::VectorXd w;
  write_lcp_velocity(problem, z, w);
  return w;
}

void write_lcp_velocity(const LcpProblem& problem, const Eigen::VectorXd& z, Eigen::VectorXd& w) {
  w = problem.q;
  if (problem.is_sparse) {
    w.noalias() += problem.sparse_M * z;
  } else {
    w.noalias() += problem.dense_M * z;
  }
}

double natural_map_residual(const Eigen::VectorXd& z, const Eigen::VectorXd& w) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const double r = std::abs(std::min(z(i), w(i)));
    // std::max would silently drop a NaN; a NaN iterate must never pass a tolerance test.
    if (std::isnan(r) || std::isnan(z(i)) || std::isnan(w(i))) {
      return std::numeric_limits<double>::quiet_NaN();
    }
    worst = std::max(worst, r);
  }
  return worst;
}

}  // namespace impactbench::solvers::lcp
