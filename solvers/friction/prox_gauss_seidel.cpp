// prox-gs: contacts are updated in order, each seeing the impulses already updated this sweep.
#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/proximal_point.hpp"

namespace impactbench::solvers::friction_detail {

Outcome solve_prox_gauss_seidel(const FrictionProblem& problem, const SolverOptions& options,
                                Eigen::VectorXd& r) {
  const auto gauss_seidel_sweep = [](const FrictionProblem& p,
                                     const std::vector<AlartCurnierParameters>& steps, double omega,
                                     Eigen::VectorXd& r_k) {
    const int d = p.dimension;
    for (int i = 0; i < p.num_contacts(); ++i) {
      const LocalVector u_i = block_row_times(p, i, r_k) + contact_part(p.q, i, d);
      contact_part(r_k, i, d) = proximal_update(p.mu(i), steps[static_cast<std::size_t>(i)], omega,
                                                contact_part(r_k, i, d), u_i);
    }
  };
  return run_proximal_point(problem, options, gauss_seidel_sweep, r);
}

}  // namespace impactbench::solvers::friction_detail
