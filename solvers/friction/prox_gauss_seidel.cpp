// prox-gs: contacts are updated in order, each seeing the impulses already updated this sweep.
// A factored problem (W = H A, the time stepper's) is swept through the velocity w = A r by
// contact blocks, as nsgs sweeps it: W is never formed, and a contact costs its rows of H and
// columns of A instead of a row of W over its neighbours.
#include <cstddef>
#include <limits>
#include <vector>

#include "solvers/common/thread_kept.hpp"
#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/factor_blocks_kernels.hpp"
#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/proximal_point.hpp"

namespace impactbench::solvers::friction_detail {
namespace {

// A formed W (dense or sparse) swept through its rows.
Outcome solve_formed(const FrictionProblem& problem, const SolverOptions& options,
                     CapacityVector& r, double entry_residual) {
  const auto gauss_seidel_sweep = [](const FrictionProblem& p,
                                     const std::vector<AlartCurnierParameters>& steps, double omega,
                                     CapacityVector& r_k) {
    const int d = p.dimension;
    for (int i = 0; i < p.num_contacts(); ++i) {
      const LocalVector u_i = block_row_times(p, i, r_k) + contact_part(p.q, i, d);
      contact_part(r_k, i, d) = proximal_update(p.mu(i), steps[static_cast<std::size_t>(i)], omega,
                                                contact_part(r_k, i, d), u_i);
    }
  };
  return run_proximal_point(problem, options, gauss_seidel_sweep, r, entry_residual);
}

struct FactoredScratch {
  std::vector<factor_blocks::RigidContactBlocks> rigid;
  CapacityVector w;
};

// A factored problem with its factor blocks. The residual after a sweep is taken at the w the
// sweep carried along (A r up to the rounding of its updates): it steers ω and picks the best
// iterate. A residual that meets the tolerance is confirmed at w = A r formed afresh, which the
// next sweep then starts from, so that convergence is decided on the exact u (as the driver
// reports it) and w does not drift for long.
Outcome solve_factored(const FrictionProblem& problem, const SolverOptions& options,
                       CapacityVector& r, const SolveEntry& entry) {
  // Kept per thread between solves (a time stepper solves one problem a step), lent to one
  // solve at a time.
  const ThreadKeptLease<FactoredScratch> scratch;
  std::vector<factor_blocks::RigidContactBlocks>& rigid = scratch->rigid;
  CapacityVector& w = scratch->w;  // A r
  factor_blocks::with_dimension(problem.dimension, [&](auto d) {
    factor_blocks::describe_rigid_contacts<d>(problem.factor_blocks, rigid);
  });
  take_entry_velocity(problem, r, entry, &rigid, w);
  const auto sweep = [&](const FrictionProblem& p, const std::vector<AlartCurnierParameters>& steps,
                         double omega, CapacityVector& r_k) {
    factor_blocks::with_dimension(p.dimension, [&](auto d) {
      constexpr int D = decltype(d)::value;
      const auto update = [&](int i, const double* row_times, const double* r_i, double* r_new) {
        const double* q_i = p.q.data() + static_cast<std::ptrdiff_t>(i) * D;
        const AlartCurnierParameters& rho = steps[static_cast<std::size_t>(i)];
        if constexpr (D == 2) {
          proximal_update_planar(p.mu(i), rho, omega, r_new[0], r_new[1], row_times[0] + q_i[0],
                                 row_times[1] + q_i[1]);
        } else {
          LocalVector u_i(D);
          for (int k = 0; k < D; ++k) u_i(k) = row_times[k] + q_i[k];
          const LocalVector next = proximal_update(
              p.mu(i), rho, omega, Eigen::Map<const Eigen::Matrix<double, D, 1>>(r_i), u_i);
          for (int k = 0; k < D; ++k) r_new[k] = next(k);
        }
      };
      factor_blocks::gauss_seidel_pass<D>(p.factor_blocks, rigid, p.num_contacts(), r_k.data(),
                                          w.data(), update);
    });
  };
  const double scale = residual_scale(problem);
  const auto residual = [&](VectorView r_k) {
    const double swept = factored_friction_residual(problem, r_k, w, &rigid, scale);
    if (!(swept <= options.tolerance)) return swept;
    write_factored_velocity(problem, r_k, w, &rigid);
    return factored_friction_residual(problem, r_k, w, &rigid, scale);
  };
  const auto reset = [&](VectorView r_k) { write_factored_velocity(problem, r_k, w, &rigid); };
  // Each W_ii formed through the descriptions the sweeps read (the sums of diagonal_blocks, to
  // the bit), without a small dynamic matrix per contact.
  const auto steps = [&](std::vector<AlartCurnierParameters>& out) {
    out.resize(static_cast<std::size_t>(problem.num_contacts()));
    return factor_blocks::with_dimension(problem.dimension, [&](auto d) {
      constexpr int D = decltype(d)::value;
      return factor_blocks::for_each_positive_diagonal<D>(
          problem.factor_blocks, &rigid, [&](int i, const double(&w_ii)[D * D]) {
            out[static_cast<std::size_t>(i)] = alart_curnier_parameters(
                Eigen::Map<const Eigen::Matrix<double, D, D, Eigen::RowMajor>>(w_ii));
          });
    });
  };
  return run_proximal_point(problem, options, sweep, r, entry.residual, residual, reset, steps);
}

}  // namespace

Outcome solve_prox_gauss_seidel(const FrictionProblem& problem, const SolverOptions& options,
                                CapacityVector& r, const SolveEntry& entry) {
  if (!problem.is_factored) return solve_formed(problem, options, r, entry.residual);
  if (!problem.factor_blocks.empty()) return solve_factored(problem, options, r, entry);
  // Factors without their blocks (an assembly of another structure): swept through W formed
  // from them, which has the same residual at the entry r only up to rounding.
  return solve_formed(formed_delassus(problem), options, r,
                      std::numeric_limits<double>::quiet_NaN());
}

}  // namespace impactbench::solvers::friction_detail
