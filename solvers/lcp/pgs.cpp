// Projected Gauss–Seidel / successive over-relaxation (Cottle–Pang–Stone §5.2):
//
//     z_i ← max(0, z_i − ω (M z + q)_i / M_ii),   i = 1 … n, in place,
//
// which converges for symmetric positive definite M and ω ∈ (0, 2). One sweep costs one pass
// over the rows of M: sparse matrices are traversed row by row (RowMajor storage) and never
// densified. The stopping test is the natural-map residual, evaluated exactly only when the
// estimate gathered during the sweep (with the partly updated z) is already below tolerance.
#include <cmath>
#include <string>

#include "solvers/common/number_text.hpp"
#include "solvers/lcp/lcp_methods.hpp"
#include "solvers/lcp/lcp_residual.hpp"

namespace impactbench::solvers::lcp {
namespace {

using RowMajorDense = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMajorSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;

double row_dot(const RowMajorDense& M, int i, const Eigen::VectorXd& z) {
  return M.row(i).dot(z);
}

double row_dot(const RowMajorSparse& M, int i, const Eigen::VectorXd& z) {
  double sum = 0.0;
  for (RowMajorSparse::InnerIterator it(M, i); it; ++it) sum += it.value() * z(it.col());
  return sum;
}

template <class Matrix>
LcpMethodResult sweep_until_converged(const Matrix& M, const LcpProblem& problem,
                                      const SolverOptions& options, double omega,
                                      Eigen::VectorXd z) {
  const int n = problem.size();
  const Eigen::VectorXd& q = problem.q;
  LcpMethodResult result;
  const Eigen::VectorXd diagonal = M.diagonal();
  for (int i = 0; i < n; ++i) {
    if (diagonal(i) == 0.0 || diagonal(i) < 0.0) {
      result.z = z;
      result.status = diagonal(i) == 0.0 ? SolverStatus::kSingular : SolverStatus::kInvalidProblem;
      result.message = "M(" + std::to_string(i) + "," + std::to_string(i) +
                       ") = " + output::number_text(diagonal(i)) +
                       ": projected Gauss-Seidel needs a positive diagonal";
      return result;
    }
  }
  const Eigen::VectorXd step = omega * diagonal.cwiseInverse();

  for (int sweep = 1; sweep <= options.max_iterations; ++sweep) {
    double estimate = 0.0;
    for (int i = 0; i < n; ++i) {
      const double w_i = row_dot(M, i, z) + q(i);
      estimate = std::max(estimate, std::abs(std::min(z(i), w_i)));
      z(i) = std::max(0.0, z(i) - step(i) * w_i);
    }
    result.iterations = sweep;
    if (!std::isfinite(estimate) || !z.allFinite()) {
      result.z = z;
      result.status = SolverStatus::kStalled;
      result.message = "iterates diverged at sweep " + std::to_string(sweep);
      return result;
    }
    if (estimate <= options.tolerance &&
        natural_map_residual(z, lcp_velocity(problem, z)) <= options.tolerance) {
      result.z = z;
      result.status = SolverStatus::kConverged;
      return result;
    }
    if (!options.keep_going(sweep, estimate)) {
      result.z = z;
      result.status = SolverStatus::kStopped;
      result.message = "stopped after sweep " + std::to_string(sweep);
      return result;
    }
  }
  result.z = z;
  result.status = SolverStatus::kMaxIterations;
  result.message = "sweep limit " + std::to_string(options.max_iterations) + " reached";
  return result;
}

}  // namespace

LcpMethodResult projected_sor(const LcpProblem& problem, const SolverOptions& options, double omega,
                              VectorView z_start) {
  if (!(omega > 0.0 && omega < 2.0)) {
    LcpMethodResult result;
    result.z = z_start;
    result.status = SolverStatus::kInvalidProblem;
    result.message = "relaxation omega = " + output::number_text(omega) + " is outside (0, 2)";
    return result;
  }
  if (problem.is_sparse) {
    return sweep_until_converged(problem.sparse_M, problem, options, omega, z_start);
  }
  // A row-major copy makes every row a contiguous dot product; it costs about one sweep.
  const RowMajorDense M = problem.dense_M;
  return sweep_until_converged(M, problem, options, omega, z_start);
}

LcpMethodResult solve_pgs(const LcpProblem& problem, const SolverOptions& options,
                          VectorView z_start) {
  return projected_sor(problem, options, 1.0, z_start);
}

}  // namespace impactbench::solvers::lcp
