#pragma once
// The small complementarity problems the event-driven integrator solves at an event instant, in
// Delassus form u = W r + q over the contacts of one instant (local frames: normal, then d
// tangential components):
//   - impulse level (simultaneous impacts): r = Λ, u_n = ζ_n⁺ + e ζ_n⁻, u_t = ζ_t⁺;
//   - acceleration level (mode consistency): r = λ, u_n = w_nᵀv̇ + ẇ_nᵀv, u_t = W_tᵀv̇ + Ẇ_tᵀv.
// A contact is either Coulomb (0 ≤ u_n ⊥ r_n ≥ 0 and the friction law on r_t, u_t) or
// normal-only (Signorini on the normal, r_t = 0; a frictionless contact or one sliding with a
// known direction whose friction has been folded into W's normal column).
//
// In the plane the problem is the standard friction LCP (exact): per Coulomb contact the
// unknowns r_n, r_t⁺, r_t⁻, β with
//   0 ≤ r_t⁺ ⊥ β + u_t ≥ 0,  0 ≤ r_t⁻ ⊥ β − u_t ≥ 0,  0 ≤ β ⊥ μ r_n − r_t⁺ − r_t⁻ ≥ 0,
// solved by solve_lcp. That LCP's matrix is not copositive-plus, and where two contacts' tangents
// are nearly parallel (a box's corners on a plank) Lemke's method can stop on a secondary ray of
// a problem that has a solution; when the configured LCP solver ends on a ray, stalls or reaches
// its iteration limit (not when it refuses the problem), a problem of at most
// solvers::lcp::kMaxEnumerationSize (14) unknowns is solved again by enumeration (exact, 2^14
// bases at most), and the solution says so. In space a problem with Coulomb contacts goes to
// solve_friction (normal-only contacts enter with μ = 0, which forces r_t = 0).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/event_driven_options.hpp"
#include "solvers/common/solver_types.hpp"

namespace impactbench::engines::event_driven {

struct LocalContactProblem {
  int tangent_dim = 1;        ///< d: 1 planar, 2 spatial; every contact has 1 + d rows.
  Eigen::MatrixXd W;          ///< (1+d)n x (1+d)n, not necessarily symmetric
  Eigen::VectorXd q;          ///< (1+d)n
  Eigen::VectorXd mu;         ///< n
  std::vector<bool> coulomb;  ///< n: true = Coulomb friction, false = normal-only

  int num_contacts() const { return static_cast<int>(mu.size()); }
  int block() const { return 1 + tangent_dim; }
};

struct LocalContactSolution {
  Eigen::VectorXd r;  ///< (1+d)n; r_t = 0 for normal-only contacts
  Eigen::VectorXd u;  ///< W r + q
  solvers::SolverStatus status = solvers::SolverStatus::kInvalidProblem;
  std::string message;
  /// Solved by enumeration after the configured LCP solver failed (its status is in `message`).
  bool enumerated = false;
  bool ok() const { return status == solvers::SolverStatus::kConverged; }
};

LocalContactSolution solve_local_contact_problem(const LocalContactProblem& problem,
                                                 const EventDrivenOptions& options);

}  // namespace impactbench::engines::event_driven
