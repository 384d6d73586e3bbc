#include "lib/engines/moreau_jean/cold_restart.hpp"

#include "solvers/friction/friction_solvers.hpp"

namespace impactbench::engines::moreau_jean {

solvers::SolverResult solve_with_cold_restart(const solvers::FrictionProblem& problem,
                                              const solvers::FrictionSolver& solver,
                                              const solvers::SolverOptions& options,
                                              const Eigen::VectorXd& warm_start,
                                              bool cold_restart) {
  solvers::SolverResult warm = solver.solve(problem, options, &warm_start);
  const bool solved = warm.converged() || warm.status == solvers::SolverStatus::kConvergedFaceted;
  if (solved || !cold_restart || !warm_start.any()) return warm;
  solvers::SolverResult cold = solver.solve(problem, options);
  const int iterations = warm.iterations + cold.iterations;
  const double seconds = warm.seconds + cold.seconds;
  const bool cold_better = cold.converged() ||
                           cold.status == solvers::SolverStatus::kConvergedFaceted ||
                           !(warm.residual <= cold.residual);
  solvers::SolverResult chosen = cold_better ? std::move(cold) : std::move(warm);
  chosen.iterations = iterations;
  chosen.seconds = seconds;
  return chosen;
}

}  // namespace impactbench::engines::moreau_jean
