#pragma once
// The one error measure of every friction solver (FCLIB/Siconos, Acary–Brémond–Huber 2018):
//   ‖r − Π_K(r − (u + g(u)))‖ / ‖q‖,  u = W r + q,  g(u) = μ‖u_t‖ e_n (De Saxcé),
// with ‖q‖ replaced by 1 when q = 0. It vanishes exactly at solutions of the Coulomb problem.
#include "solvers/friction/friction_problem.hpp"

namespace impactbench::solvers {

/// Residual for a given r and its velocity u = W r + q.
double friction_residual(const FrictionProblem& problem, const Eigen::VectorXd& r,
                         const Eigen::VectorXd& u);

/// Residual for a given r (computes u).
double friction_residual(const FrictionProblem& problem, const Eigen::VectorXd& r);

}  // namespace impactbench::solvers
