#pragma once
// The solution file of `impactbench solve --solution`, read back by `--warm-start`:
//   LCP:               i,z,w                    one row per unknown (w = Mz + q)
//   friction contact:  contact,r_n,r_t1[,r_t2],u_n,u_t1[,u_t2]   one row per contact
//                      (r the impulse/force, u = Wr + q the local velocity)
// Numbers are written so that they read back exactly.
#include <filesystem>

#include <Eigen/Core>

#include "solvers/common/solver_types.hpp"

namespace impactbench::cli {

/// What a solution file holds: `dimension` 0 for an LCP, else the friction problem's (2 or 3).
struct SolutionShape {
  int dimension = 0;
  Eigen::Index size = 0;  ///< unknowns: n of the LCP, or dimension × contacts
};

/// Writes atomically (no file is left behind on failure); throws std::runtime_error.
void write_solution_csv(const std::filesystem::path& path, const SolutionShape& shape,
                        const solvers::SolverResult& result);

/// z (LCP) or r (friction) from a file as written by write_solution_csv; throws CliError
/// (exit 1) naming the file and line for a missing column, a wrong number of rows, or a value
/// that is not a finite number.
Eigen::VectorXd read_warm_start_csv(const std::filesystem::path& path, const SolutionShape& shape);

}  // namespace impactbench::cli
