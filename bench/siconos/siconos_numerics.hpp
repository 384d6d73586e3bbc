#pragma once
// Thin adapter onto Siconos Numerics' C API (Debian libsiconos-numerics-dev, optional): the same
// LcpProblem / FrictionProblem objects our solvers take are copied into Siconos storage (dense
// column-major for LCP, sparse-block 3×3 for fc3d, Siconos' native formats for those solvers)
// and solved by a Siconos solver chosen by its id (lcp_cst.h, Friction_cst.h).
#include <string>

#include <Eigen/Core>

#include "solvers/friction/friction_problem.hpp"
#include "solvers/lcp/lcp_problem.hpp"

namespace impactbench::bench {

/// What a Siconos solve returned.
struct SiconosRun {
  Eigen::VectorXd solution;  ///< z (LCP) or r (friction contact)
  int iterations = 0;        ///< iparam[SICONOS_IPARAM_ITER_DONE]
  double own_error = 0.0;    ///< dparam[SICONOS_DPARAM_RESIDU], Siconos' own error measure
  int info = -1;             ///< the driver's return value, 0 when Siconos reports success
  /// CPU time per driver call (setup and copies excluded), over `repeats` calls in a row.
  double seconds = 0.0;
};

/// Siconos LCP solver `solver_id` (e.g. SICONOS_LCP_LEMKE) on a dense copy of M, called
/// `repeats` times in a row from z = 0 inside the timed region (a problem solved in microseconds
/// needs many calls to be timed by the process clock); the result is the last call's.
SiconosRun siconos_lcp(const solvers::LcpProblem& problem, int solver_id, double tolerance,
                       int max_iterations, int repeats = 1);

/// Siconos fc3d solver `solver_id` (e.g. SICONOS_FRICTION_3D_NSGS) on a sparse-block copy of W,
/// `repeats` calls as above. Throws std::invalid_argument for a planar problem (fc3d is spatial
/// only).
SiconosRun siconos_fc3d(const solvers::FrictionProblem& problem, int solver_id, double tolerance,
                        int max_iterations, int repeats = 1);

/// The solver's Siconos name (solver_options_id_to_name).
std::string siconos_solver_name(int solver_id);

}  // namespace impactbench::bench
