#pragma once
// The proximal-point fixed point of B.16/B.17 (normal part: the same form with the set R₊):
//   r_n ← max(0, r_n − ω ρ_n,i u_n),   r_t ← Π_{disk μ r_n}(r_t − ω ρ_t,i u_t),
// with per-contact steps from the diagonal of W (ρ_n,i = 1/W_nn, ρ_t,i = 1/mean W_tt; one
// scalar for both tangential directions, so that a fixed point on the disk boundary has u_t
// opposite to r_t: maximal dissipation) and one global factor ω adapted after each sweep from
// the FCLIB residual e_k (which is not monotone under these sweeps, so the rule tolerates it):
//   e_k > 10 · best e      → divergence: back to the best iterate, ω ← ω/2;
//   e_k > e_{k−1}          → growth: ω ← 0.7 ω (damping);
//   e_k > 0.95 · e_{k−1}   → stall: ω ← min(1.2 ω, 1.9) (longer steps);
//   ω < 1e-10              → stop with status stalled.
// The best iterate is returned when the iteration limit is reached.
// Jacobi and Gauss–Seidel differ only in the sweep (which velocity the update sees).
#include <algorithm>
#include <cmath>
#include <vector>

#include "solvers/common/function_ref.hpp"
#include "solvers/common/one_component_norm.hpp"
#include "solvers/common/select_bits.hpp"
#include "solvers/friction/alart_curnier.hpp"
#include "solvers/friction/friction_solver_list.hpp"

namespace impactbench::solvers::friction_detail {

/// One sweep: update r for every contact with steps ω ρ_i.
using ProximalSweep = FunctionRef<void(
    const FrictionProblem&, const std::vector<AlartCurnierParameters>&, double, CapacityVector&)>;

/// The B.16/B.17 update of one contact given its current velocity.
LocalVector proximal_update(double mu, const AlartCurnierParameters& rho, double omega,
                            const LocalVector& r, const LocalVector& u);

/// The same for a planar contact in scalars (r = (r_n, r_t) in and out, u = (u_n, u_t)): the
/// same arithmetic in the same order, so the same bits, without small vectors of dynamic size.
/// Inline: prox-gs's sweep calls it for every contact.
inline void proximal_update_planar(double mu, const AlartCurnierParameters& rho, double omega,
                                   double& r_n, double& r_t, double u_n, double u_t) {
  r_n = std::max(0.0, r_n - omega * rho.rho_n * u_n);
  // project_on_disk in one dimension: its norm is sqrt(x²), its scaling (radius / length) x.
  const double radius = mu * r_n;
  const double x = r_t - omega * rho.rho_t * u_t;
  const double length = one_component_norm(x);
  // The scaled value is formed in every case and picked without a branch (select_bits).
  const double scaled = (radius / length) * x;
  r_t =
      select_bits(length <= radius, x, select_bits((radius <= 0.0) | (length == 0.0), 0.0, scaled));
}

/// The residual at r (after a sweep), and what must follow r when it is set back to the best
/// iterate: a solver that sweeps a factored problem keeps w = A r along (prox_gauss_seidel.cpp).
using ProximalResidual = FunctionRef<double(VectorView)>;
using ProximalReset = FunctionRef<void(VectorView)>;
/// The steps ρ_i of every contact from its W_ii (alart_curnier_parameters, before the scaling
/// by options.rho_scale); false when a W_nn is not positive. A factored problem's solver forms
/// W_ii from the factor blocks it sweeps (prox_gauss_seidel.cpp).
using ProximalSteps = FunctionRef<bool(std::vector<AlartCurnierParameters>&)>;

/// The fixed point above from r. `entry_residual`: the residual at the entry r when the driver
/// evaluated it (NaN: evaluated here); `residual` defaults to friction_residual(problem, r),
/// `steps` to the steps from diagonal_blocks(problem).
Outcome run_proximal_point(const FrictionProblem& problem, const SolverOptions& options,
                           const ProximalSweep& sweep, CapacityVector& r, double entry_residual,
                           const ProximalResidual& residual = {}, const ProximalReset& reset = {},
                           const ProximalSteps& steps = {});

}  // namespace impactbench::solvers::friction_detail
