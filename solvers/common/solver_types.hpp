#pragma once
// Options, status and result shared by every solver (LCP and friction contact). Iterations and
// residual go into the result, never back into the options.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "solvers/common/capacity_vector.hpp"

namespace impactbench::solvers {

/// Why a solver stopped.
enum class SolverStatus {
  kConverged,         ///< Residual below tolerance.
  kMaxIterations,     ///< Iteration limit reached with the residual above tolerance.
  kRayTermination,    ///< Lemke: secondary ray, the LCP has no solution reachable by pivoting.
  kStalled,           ///< No progress (line search failed, proximal parameter exhausted).
  kNonFiniteData,     ///< NaN or Inf in the problem data (rejected before solving).
  kSingular,          ///< A pivot or diagonal block vanished (e.g. W_ii = 0).
  kInvalidProblem,    ///< Sizes inconsistent, μ < 0, or problem too large for the method.
  kConvergedFaceted,  ///< Spatial friction through an LCP: the faceted-cone LCP was solved (its
                      ///< residual below tolerance), the Coulomb (disk) residual is not.
  kStopped,           ///< The caller's monitor stopped the solve (e.g. a time limit).
};

std::string_view to_string(SolverStatus status);

/// Settings common to all solvers; each field documents its unit and default.
struct SolverOptions {
  double tolerance = 1e-10;     ///< Stop when the residual (see residuals) is below this.
  int max_iterations = 1000;    ///< Sweeps (iterative) or pivots (Lemke) or Newton steps.
  double relaxation = 1.0;      ///< ω for PSOR, in (0, 2).
  int cone_facets = 8;          ///< Facets of the polyhedral cone for spatial→LCP conversion.
  double proximal_omega = 1.0;  ///< Initial ω of prox-jacobi/prox-gs, in (0, 1.9].
  double rho_scale = 1.0;       ///< Factor > 0 on the per-contact ρ of prox-*, nsn.
  /// Whether the driver times the solve into SolverResult::seconds: two reads of the steady
  /// clock, some 30 ns each, as long as a whole Lemke solve of two unknowns takes. Callers that
  /// solve many small problems and never read the time (the event engine's contact problems,
  /// block Gauss–Seidel's local problems), or time the solves themselves (the benchmarks),
  /// turn it off; `seconds` is then NaN.
  bool measure_seconds = true;
  /// Called after every iteration (sweep, pivot, Newton step) with its number and the
  /// residual the method has at hand (NaN when it has none); returning false stops the solve
  /// with status kStopped and the current iterate. Empty: never called.
  std::function<bool(int iteration, double residual)> monitor;
  /// True unless the monitor asks to stop.
  bool keep_going(int iteration, double residual) const {
    return !monitor || monitor(iteration, residual);
  }
  /// The stop test after an iteration whose residual is at hand: kConverged when it meets the
  /// tolerance (NaN does not), kStopped when the monitor asks to stop, nothing to go on.
  std::optional<SolverStatus> stop_status(int iteration, double residual) const {
    if (residual <= tolerance) return SolverStatus::kConverged;
    if (!keep_going(iteration, residual)) return SolverStatus::kStopped;
    return std::nullopt;
  }
};

/// What a solve returns.
struct SolverResult {
  // With kept capacity: a caller that solves into the same result at every step (a time
  // stepper whose active contacts come and go) allocates nothing for them once they have grown.
  CapacityVector solution;  ///< z (LCP) or r (friction contact: [r_n, r_t...] per contact).
  CapacityVector velocity;  ///< w = Mz + q (LCP) or u = Wr + q (friction contact).
  /// A friction problem given factored (W = H A) to a solver that sweeps it (nsgs, prox-gs): A r
  /// at `solution`, formed there afresh (by nsgs's last check, at an answer found at the entry,
  /// or with `velocity` after the solve); else empty. A time stepper's M⁻¹Jᵀ r to the bit, which
  /// it then need not form again.
  CapacityVector factored_velocity;
  int iterations = 0;
  double residual = 0.0;  ///< Measured after the solve, the same way for every solver.
  /// Friction problems solved through the faceted-cone LCP: that LCP's natural-map residual
  /// ‖min(z, Mz + q)‖∞ (NaN otherwise); `residual` is then the Coulomb one.
  double faceted_residual = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0.0;  ///< Wall time of the solve; NaN when options.measure_seconds is false.
  SolverStatus status = SolverStatus::kInvalidProblem;
  std::string message;  ///< Human-readable detail when not converged.
  bool converged() const { return status == SolverStatus::kConverged; }
};

}  // namespace impactbench::solvers

namespace impactbench::solvers {

/// A registry entry: `--solver NAME`, the tests and the benchmarks enumerate the same list.
struct SolverInfo {
  std::string name;         ///< e.g. "lemke", "nsgs"
  std::string description;  ///< one line
  double default_tolerance = 1e-10;
  int default_max_iterations = 1000;
  bool iterative = true;  ///< false for pivoting/enumeration methods
};

}  // namespace impactbench::solvers
