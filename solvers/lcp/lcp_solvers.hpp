#pragma once
// Entry point for every LCP solver: one driver validates the data (sizes, NaN/Inf), handles
// trivial cases, dispatches by name and measures the natural-map residual ‖min(z, Mz + q)‖∞
// the same way for all solvers.
#include <string_view>
#include <vector>

#include "solvers/common/solver_types.hpp"
#include "solvers/common/warm_start.hpp"
#include "solvers/lcp/lcp_problem.hpp"

namespace impactbench::solvers {

/// Names: "lemke", "pgs", "psor", "newton-fb", "enum". Throws std::invalid_argument for an
/// unknown name; every other failure is reported in the result's status.
SolverResult solve_lcp(const LcpProblem& problem, std::string_view solver,
                       const SolverOptions& options = {}, WarmStart warm_start = nullptr);

/// The same solve into `result`, every field of which it sets. The storage of result.solution
/// and result.velocity is reused where the method allows (Lemke does): a caller solving many
/// problems in a row into one result allocates nothing per solve for them, as Siconos' driver
/// writes into the caller's z and w.
void solve_lcp(const LcpProblem& problem, std::string_view solver, const SolverOptions& options,
               WarmStart warm_start, SolverResult& result);

const std::vector<SolverInfo>& lcp_solvers();

}  // namespace impactbench::solvers
