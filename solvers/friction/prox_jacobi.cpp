// prox-jacobi: every contact's B.16/B.17 update sees the velocity of the previous iterate.
#include "solvers/common/thread_kept.hpp"
#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/proximal_point.hpp"

namespace impactbench::solvers::friction_detail {
namespace {

// u of the previous iterate, kept per thread between sweeps and solves (a time stepper solves
// one problem a step).
struct JacobiScratch {
  CapacityVector velocity;
};

}  // namespace

Outcome solve_prox_jacobi(const FrictionProblem& problem, const SolverOptions& options,
                          CapacityVector& r, const SolveEntry& entry) {
  const ThreadKeptLease<JacobiScratch> scratch;
  CapacityVector& u = scratch->velocity;
  const auto jacobi_sweep = [&u](const FrictionProblem& p,
                                 const std::vector<AlartCurnierParameters>& steps, double omega,
                                 CapacityVector& r_k) {
    write_contact_velocity(p, r_k, u);  // contact_velocity's bits, into kept storage
    const int d = p.dimension;
    for (int i = 0; i < p.num_contacts(); ++i) {
      contact_part(r_k, i, d) = proximal_update(p.mu(i), steps[static_cast<std::size_t>(i)], omega,
                                                contact_part(r_k, i, d), contact_part(u, i, d));
    }
  };
  return run_proximal_point(problem, options, jacobi_sweep, r, entry.residual);
}

}  // namespace impactbench::solvers::friction_detail
