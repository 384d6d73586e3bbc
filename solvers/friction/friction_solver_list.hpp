#pragma once
// Internal: the solver functions behind solve_friction. Each improves r in place (r holds the
// warm start or zeros on entry) on a problem the driver has already validated, and reports
// iterations and why it stopped; the driver measures the residual and sets the final status.
#include <limits>
#include <string>
#include <string_view>

#include <vector>
#include "solvers/common/solver_types.hpp"

#include "solvers/friction/coulomb_cone.hpp"
#include "solvers/friction/friction_problem.hpp"

namespace impactbench::solvers::factor_blocks {
struct RigidContactBlocks;
}

namespace impactbench::solvers::friction_detail {

struct Outcome {
  int iterations = 0;
  SolverStatus status = SolverStatus::kMaxIterations;
  std::string message;
  /// Spatial solves through the faceted-cone LCP: that LCP's natural-map residual (NaN else).
  double faceted_residual = std::numeric_limits<double>::quiet_NaN();
  /// u = W r + q at the returned r, when the solver last evaluated it there (empty otherwise):
  /// the driver's final residual reuses it instead of another product with W.
  CapacityVector velocity{};
  /// friction_residual at the returned r and `velocity`, when the solver evaluated it there with
  /// that velocity (NaN otherwise): the driver reports it instead of evaluating it again.
  double residual = std::numeric_limits<double>::quiet_NaN();
};

/// The refusal of a problem with a diagonal entry W_nn that is not positive (or NaN), which the
/// local steps and problems of the sweeping solvers divide by.
inline Outcome nonpositive_normal_diagonal() {
  return {0, SolverStatus::kSingular, "a diagonal entry W_nn is not positive"};
}

/// What the driver evaluated at r on entry, before it called the solver: a solver may start
/// from it instead of evaluating it again.
struct SolveEntry {
  double residual = std::numeric_limits<double>::quiet_NaN();  ///< friction_residual at r
  /// A r at r of a factored problem (W = H A), in storage the driver keeps per thread: the
  /// solver may take it (swap in storage of the same size); null for other problems.
  CapacityVector* factored_velocity = nullptr;
  /// A factored problem's SolverResult::factored_velocity, which the driver has emptied: a
  /// solver that formed A r afresh at the r it returns writes it there. Null for other problems.
  CapacityVector* answer_factored_velocity = nullptr;
};

/// A r at the entry r of a factored problem into `velocity`: the driver's (swapped in: the same
/// bits) when it formed one of the right size, else formed here (`rigid` as for
/// write_factored_velocity).
void take_entry_velocity(const FrictionProblem& problem, VectorView r, const SolveEntry& entry,
                         const std::vector<factor_blocks::RigidContactBlocks>* rigid,
                         CapacityVector& velocity);

/// Storage for an Outcome's velocity, kept per thread: a solver takes it (swap) into the Outcome
/// it fills, and the driver gives it back after copying the answer out, so that a time stepper
/// solving one problem a step does not allocate u anew at each solve.
CapacityVector& kept_outcome_velocity();

Outcome solve_prox_jacobi(const FrictionProblem& problem, const SolverOptions& options,
                          CapacityVector& r, const SolveEntry& entry);
/// A factored problem is swept through w = A r, as nsgs sweeps it, when it has factor blocks.
Outcome solve_prox_gauss_seidel(const FrictionProblem& problem, const SolverOptions& options,
                                CapacityVector& r, const SolveEntry& entry);
Outcome solve_nonsmooth_gauss_seidel(const FrictionProblem& problem, const SolverOptions& options,
                                     CapacityVector& r, const SolveEntry& entry);
Outcome solve_semismooth_newton(const FrictionProblem& problem, const SolverOptions& options,
                                CapacityVector& r);
/// pgs on the LCP form, by contact blocks with exact local pivoting solves (the scalar PGS
/// cannot: the slack rows have a zero diagonal).
Outcome solve_lcp_block_gauss_seidel(const FrictionProblem& problem, const SolverOptions& options,
                                     CapacityVector& r);
Outcome solve_through_lcp(const FrictionProblem& problem, const SolverOptions& options,
                          std::string_view lcp_solver, CapacityVector& r);

/// One nonsmooth Gauss–Seidel sweep (shared by nsgs and the Newton fallback); false if a local
/// solve failed to reach machine precision.
bool nonsmooth_gauss_seidel_sweep(const FrictionProblem& problem,
                                  const std::vector<LocalMatrix>& diagonal_blocks,
                                  CapacityVector& r);

}  // namespace impactbench::solvers::friction_detail
