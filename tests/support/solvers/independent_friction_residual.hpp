#pragma once
// The FCLIB residual ‖r − Π_K(r − (u + g(u)))‖ / ‖q‖ (‖q‖ → 1 when q = 0), u = W r + q,
// g(u) = μ‖u_t‖ e_n, recomputed from scratch for the tests: u by Eigen's own product and the
// projection on the friction cone K = {‖r_t‖ ≤ μ r_n} written here from its 2-D geometry, so a
// fault in the solvers' residual or cone code (solvers/friction) does not cancel out.
#include <Eigen/Core>

#include "solvers/friction/friction_problem.hpp"

namespace impactbench::test_support {

double independent_friction_residual(const solvers::FrictionProblem& problem,
                                     const Eigen::VectorXd& r);

/// How far a residual evaluated with a velocity u other than W r + q (a solver's running
/// velocity) may lie from independent_friction_residual(r): Π_K is non-expansive and μ‖u_t‖ is
/// μ-Lipschitz, so |ρ(u) − ρ(W r + q)| ≤ (1 + max μ) ‖u − (W r + q)‖ / ‖q‖; plus the
/// round-off of the two evaluations, a few ulps of |r| + |W||r| + |q| (large where ‖r‖ ≫ ‖q‖).
double residual_allowance_for_velocity(const solvers::FrictionProblem& problem,
                                       const Eigen::VectorXd& r, const Eigen::VectorXd& u);

}  // namespace impactbench::test_support
