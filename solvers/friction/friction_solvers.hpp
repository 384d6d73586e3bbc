#pragma once
// Entry point for every friction-contact solver: one driver validates the data (sizes, μ ≥ 0,
// NaN/Inf), dispatches by name and measures the FCLIB/Siconos residual
// ‖r − Π_K(r − (u + g(u)))‖ / ‖q‖ (Acary–Brémond–Huber 2018) the same way for all solvers.
#include <string_view>
#include <vector>

#include "solvers/common/solver_types.hpp"
#include "solvers/common/warm_start.hpp"
#include "solvers/friction/friction_problem.hpp"

namespace impactbench::solvers {

namespace friction_detail {
struct RegistryEntry;
}

/// One friction-contact solver, looked up by name once: a caller that solves every step (the
/// Moreau–Jean stepper) resolves its solver at construction instead of by name per solve.
class FrictionSolver {
 public:
  /// Throws std::invalid_argument for an unknown name, listing the known ones.
  explicit FrictionSolver(std::string_view name);

  const SolverInfo& info() const;
  /// Reaches the problem through its LCP form: exact in the plane, the faceted cone in space.
  bool solves_through_lcp() const;
  /// Sweeps W in its factors H A; the other solvers are given W formed.
  bool sweeps_factored_delassus() const;
  /// The driver: validation, the solve, the FCLIB residual (see solve_friction).
  SolverResult solve(const FrictionProblem& problem, const SolverOptions& options = {},
                     WarmStart warm_start = nullptr) const;
  /// The same into `result`, whose vectors keep their storage: a caller that keeps it from
  /// solve to solve allocates nothing in the driver once it has solved the largest problem
  /// (twice for a factored one: the entry's A r and the sweep's trade storage).
  /// `warm_start` may not be result.velocity.
  void solve(const FrictionProblem& problem, const SolverOptions& options, WarmStart warm_start,
             SolverResult& result) const;

 private:
  const friction_detail::RegistryEntry* entry_;  // an entry of the static registry
};

/// Names: "prox-jacobi", "prox-gs", "nsgs", "nsn", and "lemke", "pgs" through the LCP
/// conversions (exact in the plane, faceted cone in space). Throws std::invalid_argument for an
/// unknown name; every other failure is reported in the result's status.
SolverResult solve_friction(const FrictionProblem& problem, std::string_view solver,
                            const SolverOptions& options = {}, WarmStart warm_start = nullptr);

const std::vector<SolverInfo>& friction_solvers();

}  // namespace impactbench::solvers
