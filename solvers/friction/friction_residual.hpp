#pragma once
// The one error measure of every friction solver (FCLIB/Siconos, Acary–Brémond–Huber 2018):
//   ‖r − Π_K(r − (u + g(u)))‖ / ‖q‖,  u = W r + q,  g(u) = μ‖u_t‖ e_n (De Saxcé),
// with ‖q‖ replaced by 1 when q = 0. It vanishes exactly at solutions of the Coulomb problem.
#include <vector>

#include "solvers/friction/friction_problem.hpp"

namespace impactbench::solvers {

/// Residual for a given r and its velocity u = W r + q.
double friction_residual(const FrictionProblem& problem, VectorView r, VectorView u);

/// The residual's divisor, ‖q‖ (1 when q = 0): a solver that evaluates the residual at every
/// sweep forms it once per solve and passes it to the overloads below.
double residual_scale(const FrictionProblem& problem);

/// friction_residual(problem, r, u) with its divisor given (residual_scale(problem)).
double friction_residual(const FrictionProblem& problem, VectorView r, VectorView u, double scale);

namespace factor_blocks {
struct RigidContactBlocks;
}

/// Residual at r of a factored problem with factor blocks, given its velocity w = A r (and the
/// contacts' descriptions, or null): u = H w + q is formed contact by contact and never stored.
/// The same bits as friction_residual(problem, r, u) after write_factored_contact_velocity.
double factored_friction_residual(const FrictionProblem& problem, VectorView r, VectorView w,
                                  const std::vector<factor_blocks::RigidContactBlocks>* rigid);
/// The same with its divisor given (residual_scale(problem)).
double factored_friction_residual(const FrictionProblem& problem, VectorView r, VectorView w,
                                  const std::vector<factor_blocks::RigidContactBlocks>* rigid,
                                  double scale);

/// Residual for a given r (computes u).
double friction_residual(const FrictionProblem& problem, VectorView r);

}  // namespace impactbench::solvers
