// Enumeration of complementary bases: for every subset S of {1 … n} set z_i = 0 off S and solve
// M_SS z_S = −q_S (then w_S = 0); the pair (z, w = M z + q) solves the LCP when z_S ≥ 0 and
// w ≥ 0 off S. The subsystem is solved in the least-squares sense by a complete orthogonal
// decomposition so that singular but consistent bases (positive semidefinite M) still count.
// Cost 2^n small solves, hence the size limit; this is the oracle the tests compare against.
#include <limits>
#include <string>
#include <vector>

#include <Eigen/QR>

#include "solvers/common/number_text.hpp"
#include "solvers/lcp/lcp_methods.hpp"
#include "solvers/lcp/lcp_residual.hpp"

namespace impactbench::solvers::lcp {

LcpMethodResult solve_enumeration(const LcpProblem& problem, const SolverOptions& options,
                                  VectorView /*z_start: every basis is tried*/) {
  const int n = problem.size();
  LcpMethodResult result;
  result.z = Eigen::VectorXd::Zero(n);
  if (n > kMaxEnumerationSize) {
    result.status = SolverStatus::kInvalidProblem;
    result.message = "enumeration of 2^" + std::to_string(n) +
                     " bases refused: n = " + std::to_string(n) + " exceeds " +
                     std::to_string(kMaxEnumerationSize);
    return result;
  }
  // A sparse M formed dense once; a dense M read where it is.
  Eigen::MatrixXd formed;
  if (problem.is_sparse) formed = Eigen::MatrixXd(problem.sparse_M);
  const Eigen::MatrixXd& M = problem.is_sparse ? formed : problem.dense_M;
  double best = std::numeric_limits<double>::infinity();
  std::vector<int> support;
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    support.clear();
    for (int i = 0; i < n; ++i) {
      if (mask & (1u << i)) support.push_back(i);
    }
    const auto size = static_cast<Eigen::Index>(support.size());
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    if (size > 0) {
      Eigen::MatrixXd block(size, size);
      Eigen::VectorXd rhs(size);
      for (Eigen::Index r = 0; r < size; ++r) {
        rhs(r) = -problem.q(support[r]);
        for (Eigen::Index c = 0; c < size; ++c) block(r, c) = M(support[r], support[c]);
      }
      const Eigen::VectorXd zs = block.completeOrthogonalDecomposition().solve(rhs);
      for (Eigen::Index r = 0; r < size; ++r) z(support[r]) = zs(r);
    }
    const double residual = natural_map_residual(z, Eigen::VectorXd(M * z + problem.q));
    if (residual < best) {
      best = residual;
      result.z = z;
    }
  }
  result.iterations = 1 << n;
  if (best <= options.tolerance) {
    result.status = SolverStatus::kConverged;
  } else {
    result.status = SolverStatus::kStalled;
    result.message = "no complementary basis solves the LCP (smallest residual " +
                     output::number_text(best) + ")";
  }
  return result;
}

}  // namespace impactbench::solvers::lcp
