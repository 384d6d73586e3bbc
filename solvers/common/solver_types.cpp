#include "solvers/common/solver_types.hpp"

namespace impactbench::solvers {

std::string_view to_string(SolverStatus status) {
  switch (status) {
    case SolverStatus::kConverged:
      return "converged";
    case SolverStatus::kMaxIterations:
      return "max-iterations";
    case SolverStatus::kRayTermination:
      return "ray-termination";
    case SolverStatus::kStalled:
      return "stalled";
    case SolverStatus::kNonFiniteData:
      return "non-finite-data";
    case SolverStatus::kSingular:
      return "singular";
    case SolverStatus::kInvalidProblem:
      return "invalid-problem";
    case SolverStatus::kConvergedFaceted:
      return "converged-faceted-cone";
    case SolverStatus::kStopped:
      return "stopped";
  }
  return "unknown";
}

}  // namespace impactbench::solvers
