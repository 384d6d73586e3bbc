#include "solvers/lcp/lcp_residual.hpp"

#include <cmath>
#include <limits>

namespace impactbench::solvers::lcp {

CapacityVector lcp_velocity(const LcpProblem& problem, VectorView z) {
  CapacityVector w;
  write_lcp_velocity(problem, z, w);
  return w;
}

void write_lcp_velocity(const LcpProblem& problem, VectorView z, CapacityVector& w) {
  w = problem.q;
  if (problem.is_sparse) {
    w.add_noalias(problem.sparse_M * z);
  } else {
    w.add_noalias(problem.dense_M * z);
  }
}

double natural_map_residual(VectorView z, VectorView w) {
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
