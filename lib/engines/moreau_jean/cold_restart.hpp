#pragma once
// One step's contact solve, warm-started from the previous step's impulses and, when that ends
// unconverged, repeated from zero impulses. A warm start is usually the cheapest way in, but a
// Newton method can stall from one (nsn on pile steps: unconverged after 1,000 steps from the
// previous impulses, converged in 13–25 from zero on the same problems).
#include <Eigen/Core>

#include "solvers/common/solver_types.hpp"
#include "solvers/friction/friction_problem.hpp"
#include "solvers/friction/friction_solvers.hpp"

namespace impactbench::engines::moreau_jean {

/// Into `result` (its vectors keep their storage): the warm-started result if it converged (or
/// the restart is off, or the warm start is zero); otherwise the restart's result if it
/// converged, else whichever of the two ended with the smaller residual. Iterations and solve
/// time are those of both solves.
void solve_with_cold_restart(const solvers::FrictionProblem& problem,
                             const solvers::FrictionSolver& solver,
                             const solvers::SolverOptions& options,
                             const solvers::CapacityVector& warm_start, bool cold_restart,
                             solvers::SolverResult& result);

}  // namespace impactbench::engines::moreau_jean
