// nsgs: nonsmooth Gauss–Seidel. Contact by contact, the local problem
//   u_i = W_ii r_i + b_i,  b_i = q_i + Σ_{j≠i} W_ij r_j   (current r)
// is solved exactly (single_contact_solver), then the global residual decides convergence.
#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solver_list.hpp"
#include "solvers/friction/single_contact_solver.hpp"

namespace impactbench::solvers::friction_detail {

bool nonsmooth_gauss_seidel_sweep(const FrictionProblem& problem,
                                  const std::vector<LocalMatrix>& diagonal_blocks,
                                  Eigen::VectorXd& r) {
  const int d = problem.dimension;
  bool all_exact = true;
  for (int i = 0; i < problem.num_contacts(); ++i) {
    const LocalMatrix& w_ii = diagonal_blocks[static_cast<std::size_t>(i)];
    LocalVector r_i = contact_part(r, i, d);
    const LocalVector b_i =
        block_row_times(problem, i, r) - w_ii * r_i + contact_part(problem.q, i, d);
    all_exact = solve_single_contact(w_ii, b_i, problem.mu(i), r_i) && all_exact;
    contact_part(r, i, d) = r_i;
  }
  return all_exact;
}

Outcome solve_nonsmooth_gauss_seidel(const FrictionProblem& problem, const SolverOptions& options,
                                     Eigen::VectorXd& r) {
  const std::vector<LocalMatrix> blocks = diagonal_blocks(problem);
  for (const LocalMatrix& block : blocks) {
    if (!(block(0, 0) > 0.0))
      return {0, SolverStatus::kSingular, "a diagonal entry W_nn is not positive"};
  }
  Outcome outcome;
  for (outcome.iterations = 1; outcome.iterations <= options.max_iterations; ++outcome.iterations) {
    nonsmooth_gauss_seidel_sweep(problem, blocks, r);
    if (!r.allFinite())
      return {outcome.iterations, SolverStatus::kStalled, "iterate became non-finite"};
    const double residual = friction_residual(problem, r);
    if (residual <= options.tolerance) {
      outcome.status = SolverStatus::kConverged;
      return outcome;
    }
    if (!options.keep_going(outcome.iterations, residual))
      return {outcome.iterations, SolverStatus::kStopped, "stopped by the caller"};
  }
  outcome.iterations = options.max_iterations;
  outcome.message = "iteration limit reached";
  return outcome;
}

}  // namespace impactbench::solvers::friction_detail
