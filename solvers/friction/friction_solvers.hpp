#pragma once
// Entry point for every friction-contact solver: one driver validates the data (sizes, μ ≥ 0,
// NaN/Inf), dispatches by name and measures the FCLIB/Siconos residual
// ‖r − Π_K(r − (u + g(u)))‖ / ‖q‖ (Acary–Brémond–Huber 2018) the same way for all solvers.
#include <string_view>
#include <vector>

#include "solvers/common/solver_types.hpp"
#include "solvers/friction/friction_problem.hpp"

namespace impactbench::solvers {

/// Names: "prox-jacobi", "prox-gs", "nsgs", "nsn", and "lemke", "pgs" through the LCP
/// conversions (exact in the plane, faceted cone in space). Throws std::invalid_argument for an
/// unknown name; every other failure is reported in the result's status.
SolverResult solve_friction(const FrictionProblem& problem, std::string_view solver,
                            const SolverOptions& options = {},
                            const Eigen::VectorXd* warm_start = nullptr);

const std::vector<SolverInfo>& friction_solvers();

}  // namespace impactbench::solvers
