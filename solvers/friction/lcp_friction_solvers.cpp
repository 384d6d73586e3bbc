// lemke: friction contact solved as an LCP (lcp_conversion.hpp) by the LCP solvers, then
// converted back to r. Exact in the plane; in space the faceted cone's solution differs from
// the disk's, so the driver's friction residual (on the true problem) can stay above tol.
#include <string>

#include "solvers/friction/friction_solver_list.hpp"
#include "solvers/friction/lcp_conversion.hpp"
#include "solvers/lcp/lcp_solvers.hpp"

namespace impactbench::solvers::friction_detail {

Outcome solve_through_lcp(const FrictionProblem& problem, const SolverOptions& options,
                          std::string_view lcp_solver, CapacityVector& r) {
  const FrictionLcp conversion = friction_to_lcp(problem, options.cone_facets);
  const Eigen::VectorXd start = lcp_point_from_impulse(problem, conversion, r);
  const SolverResult lcp_result = solve_lcp(conversion.lcp, lcp_solver, options, &start);
  Outcome outcome{lcp_result.iterations, lcp_result.status, lcp_result.message};
  if (lcp_result.solution.size() == conversion.lcp.size()) {
    r = impulse_from_lcp(conversion, lcp_result.solution);
  }
  if (problem.dimension == 3) {
    outcome.faceted_residual = lcp_result.residual;
    outcome.message = "faceted cone with " + std::to_string(conversion.directions) +
                      " facets (LCP " + std::string(to_string(lcp_result.status)) + ")" +
                      (lcp_result.message.empty() ? "" : ": " + lcp_result.message);
  }
  return outcome;
}

}  // namespace impactbench::solvers::friction_detail
