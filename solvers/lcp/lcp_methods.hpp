#pragma once
// The individual LCP methods behind solve_lcp (solvers/lcp/lcp_solvers.hpp). Call them through
// solve_lcp: the driver has already checked sizes and finiteness, handled q ≥ 0, clipped the
// warm start to z ≥ 0, and it recomputes the residual and the final status afterwards.
#include <string>

#include <Eigen/Core>

#include "solvers/common/solver_types.hpp"
#include "solvers/lcp/lcp_problem.hpp"

namespace impactbench::solvers::lcp {

/// What a method hands back to the driver; the driver turns it into a SolverResult.
struct LcpMethodResult {
  CapacityVector z;
  /// w = M z + q and the natural-map residual of z, when the method computed them for its
  /// answer (has_velocity); the driver then uses them instead of computing them again.
  CapacityVector w;
  bool has_velocity = false;
  double residual = 0.0;
  int iterations = 0;  ///< pivots (Lemke), sweeps (PGS/PSOR), Newton steps, bases (enum)
  SolverStatus status = SolverStatus::kStalled;
  std::string message;
};

/// The driver calls every method with this signature: `z_start` is the clipped warm start (or
/// zero) for the iterative methods, empty for the pivoting ones (Lemke, enumeration), which ignore
/// it. `result` arrives with the other fields at their defaults and with z and w (of any size and
/// content: the caller's last answer) and an empty message holding storage a method may reuse, so
/// that a caller solving many small problems into one SolverResult allocates nothing per solve.
using LcpMethod = void (*)(const LcpProblem& problem, const SolverOptions& options,
                           VectorView z_start, LcpMethodResult& result);

/// Lemke's complementary pivoting, covering vector d = 1, lexicographic ratio test (no cycling).
/// Reuses the storage of result.z and result.w.
void solve_lemke(const LcpProblem& problem, const SolverOptions& options, VectorView z_start,
                 LcpMethodResult& result);
/// Lemke on the tableau whose size is known only at run time, whatever the problem's size: the
/// reference that the tableaux of a size fixed at compile time (2 to 12 unknowns) must match bit
/// for bit (tests/solvers/lcp_lemke_fixed_size_test.cpp).
void solve_lemke_at_run_time_size(const LcpProblem& problem, const SolverOptions& options,
                                  LcpMethodResult& result);

// The other methods return a fresh result; the driver adapts them (lcp_solvers.cpp).
/// Projected Gauss–Seidel (ω = 1).
LcpMethodResult solve_pgs(const LcpProblem& problem, const SolverOptions& options,
                          VectorView z_start);
/// Projected successive over-relaxation with ω = options.relaxation ∈ (0, 2).
LcpMethodResult solve_psor(const LcpProblem& problem, const SolverOptions& options,
                           VectorView z_start);
/// Semismooth Newton on the Fischer–Burmeister function with an Armijo line search.
LcpMethodResult solve_newton_fb(const LcpProblem& problem, const SolverOptions& options,
                                VectorView z_start);
/// Enumeration of all 2^n complementary bases (n ≤ kMaxEnumerationSize): the test oracle.
LcpMethodResult solve_enumeration(const LcpProblem& problem, const SolverOptions& options,
                                  VectorView z_start);

inline constexpr int kMaxEnumerationSize = 14;

/// Projected SOR sweeps shared by PGS and PSOR (pgs.cpp); ω must lie in (0, 2).
LcpMethodResult projected_sor(const LcpProblem& problem, const SolverOptions& options, double omega,
                              VectorView z_start);

}  // namespace impactbench::solvers::lcp
