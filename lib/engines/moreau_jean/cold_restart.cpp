#include "lib/engines/moreau_jean/cold_restart.hpp"

#include <utility>

#include "solvers/friction/friction_solvers.hpp"

namespace impactbench::engines::moreau_jean {

void solve_with_cold_restart(const solvers::FrictionProblem& problem,
                             const solvers::FrictionSolver& solver,
                             const solvers::SolverOptions& options,
                             const solvers::CapacityVector& warm_start, bool cold_restart,
                             solvers::SolverResult& result) {
  solvers::SolverResult& warm = result;
  solver.solve(problem, options, &warm_start, warm);
  const bool solved = warm.converged() || warm.status == solvers::SolverStatus::kConvergedFaceted;
  if (solved || !cold_restart || !warm_start.any()) return;
  solvers::SolverResult cold = solver.solve(problem, options);
  const int iterations = warm.iterations + cold.iterations;
  const double seconds = warm.seconds + cold.seconds;
  const bool cold_better = cold.converged() ||
                           cold.status == solvers::SolverStatus::kConvergedFaceted ||
                           !(warm.residual <= cold.residual);
  if (cold_better) std::swap(result, cold);
  result.iterations = iterations;
  result.seconds = seconds;
}

}  // namespace impactbench::engines::moreau_jean
