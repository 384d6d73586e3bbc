// Projected SOR: the sweeps of pgs.cpp with the relaxation ω = options.relaxation. ω > 1
// over-relaxes (often fewer sweeps on well-conditioned SPD problems), ω < 1 damps.
#include "solvers/lcp/lcp_methods.hpp"

namespace impactbench::solvers::lcp {

LcpMethodResult solve_psor(const LcpProblem& problem, const SolverOptions& options,
                           VectorView z_start) {
  return projected_sor(problem, options, options.relaxation, z_start);
}

}  // namespace impactbench::solvers::lcp
