#include "lib/engines/moreau_jean/moreau_jean_results.hpp"

namespace impactbench::engines::moreau_jean {

std::string to_string(RunStatus status) {
  switch (status) {
    case RunStatus::kCompleted:
      return "completed";
    case RunStatus::kSolverFailed:
      return "solver-failed";
    case RunStatus::kDiverged:
      return "diverged";
  }
  return "unknown";
}

}  // namespace impactbench::engines::moreau_jean
