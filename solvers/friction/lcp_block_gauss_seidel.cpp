// pgs on a friction problem: projected Gauss–Seidel on the LCP of lcp_conversion.hpp, by
// contact blocks. The scalar update z_i ← max(0, z_i − w_i / M_ii) cannot run there: the slack
// β of each contact has M_ββ = 0 (w_β = μ r_n − Σα does not involve β). Taking each contact's
// k + 2 variables z_I together, the diagonal block M_II is the LCP of one faceted contact, which
// a pivoting method solves exactly, so a sweep sets, contact after contact,
//   z_I ← solution of LCP(M_II, q_I + Σ_{J≠I} M_IJ z_J)
// (block projected Gauss–Seidel, Cottle–Pang–Stone §5.2; Siconos' lcp_nsgs_SBM). The plane's
// LCP is exact, so there pgs stops when the friction residual of r = T z is below the
// tolerance, like every friction solver; in space it converges to the faceted cone's solution
// (as lemke does) and stops when the LCP's natural-map residual ‖min(z, Mz + q)‖∞ is.
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solver_list.hpp"
#include "solvers/friction/lcp_conversion.hpp"
#include "solvers/lcp/lcp_residual.hpp"
#include "solvers/lcp/lcp_solvers.hpp"

namespace impactbench::solvers::friction_detail {
namespace {

using RowMajorSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// Rows [first, first + m) of M times z, without the diagonal block's own contribution.
/// Dense M is column-major: the row block times z is one matrix-vector product (reading the
/// rows one by one would stride through memory).
Eigen::VectorXd off_block_product(const LcpProblem& lcp, const Eigen::MatrixXd& diagonal_block,
                                  int first, int m, const Eigen::VectorXd& z) {
  if (!lcp.is_sparse) {
    return lcp.dense_M.middleRows(first, m) * z - diagonal_block * z.segment(first, m);
  }
  Eigen::VectorXd result(m);
  for (int row = 0; row < m; ++row) {
    double sum = 0.0;
    for (RowMajorSparse::InnerIterator it(lcp.sparse_M, first + row); it; ++it) {
      const auto col = it.col();
      if (col < first || col >= first + m) sum += it.value() * z(col);
    }
    result(row) = sum;
  }
  return result;
}

Eigen::MatrixXd diagonal_lcp_block(const LcpProblem& lcp, int first, int m) {
  if (!lcp.is_sparse) return lcp.dense_M.block(first, first, m, m);
  return Eigen::MatrixXd(lcp.sparse_M.block(first, first, m, m));
}

}  // namespace

Outcome solve_lcp_block_gauss_seidel(const FrictionProblem& problem, const SolverOptions& options,
                                     CapacityVector& r) {
  const FrictionLcp conversion = friction_to_lcp(problem, options.cone_facets);
  const LcpProblem& lcp = conversion.lcp;
  const int m = conversion.variables_per_contact();
  std::vector<Eigen::MatrixXd> blocks;
  blocks.reserve(static_cast<std::size_t>(problem.num_contacts()));
  for (int i = 0; i < problem.num_contacts(); ++i) {
    blocks.push_back(diagonal_lcp_block(lcp, i * m, m));
  }
  // Planar blocks (4 unknowns) are solved by enumerating their 16 complementary bases: exact
  // even when the block is degenerate (sticking: w_α± = β ± u_t = 0 with α∓ = 0), where Lemke's
  // final basis can be ill-conditioned (local residual 9e-12 measured on a plank-box step, which
  // stalled the sweeps at 5e-10 while nsgs converged in 11). Spatial blocks (k + 2 = 10
  // unknowns, 1024 bases) use Lemke.
  const std::string_view local_solver = m <= 4 ? "enum" : "lemke";
  SolverOptions local_options;
  local_options.tolerance = 1e-14;
  local_options.max_iterations = 50 * m;
  local_options.measure_seconds = false;  // one solve per contact and sweep; the sweeps are timed
  Eigen::VectorXd z = lcp_point_from_impulse(problem, conversion, r);
  Outcome outcome;
  for (outcome.iterations = 1; outcome.iterations <= options.max_iterations; ++outcome.iterations) {
    for (int i = 0; i < problem.num_contacts(); ++i) {
      const LcpProblem local = LcpProblem::dense(
          blocks[static_cast<std::size_t>(i)],
          lcp.q.segment(i * m, m) +
              off_block_product(lcp, blocks[static_cast<std::size_t>(i)], i * m, m, z));
      const SolverResult solved = solve_lcp(local, local_solver, local_options);
      if (solved.solution.size() != m || !solved.solution.allFinite()) {
        r = impulse_from_lcp(conversion, z);
        return {outcome.iterations, solved.status,
                "local LCP of contact " + std::to_string(i) + " not solved by Lemke (" +
                    std::string(to_string(solved.status)) + "): " + solved.message};
      }
      z.segment(i * m, m) = solved.solution;
    }
    r = impulse_from_lcp(conversion, z);
    const double residual = problem.dimension == 2
                                ? friction_residual(problem, r)
                                : lcp::natural_map_residual(z, lcp::lcp_velocity(lcp, z));
    if (const auto stop = options.stop_status(outcome.iterations, residual)) {
      outcome.status = *stop;
      break;
    }
  }
  outcome.iterations = std::min(outcome.iterations, options.max_iterations);
  if (problem.dimension == 3) {
    outcome.faceted_residual = lcp::natural_map_residual(z, lcp::lcp_velocity(lcp, z));
    outcome.message = "faceted cone with " + std::to_string(conversion.directions) + " facets";
  }
  return outcome;
}

}  // namespace impactbench::solvers::friction_detail
