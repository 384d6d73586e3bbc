#pragma once
// Consistent modes for the closed contacts after an event, from the acceleration-level
// complementarity problem (not by trial and error): with a = [w_nᵀv̇ + ẇ_nᵀv; W_tᵀv̇ + Ẇ_tᵀv],
//     0 ≤ a_n ⊥ λ_n ≥ 0,
//     sticking contact (ζ_t = 0): Coulomb at acceleration level — a_t = 0 with ‖λ_t‖ ≤ μλ_n
//       (stick), or λ_t = −μλ_n ε(a_t) (slip, in the direction of the tendency a_t);
//     sliding contact (ζ_t ≠ 0): λ_t = −μλ_n ε(ζ_t), folded into the normal column.
// Delassus form a = W λ + q with W = A M⁻¹ G and q = A M⁻¹(S u − H) + drift, solved by
// solve_local_contact_problem (planar: the exact friction LCP; spatial: friction contact).
//
// Guards that fired sit exactly on a mode boundary, where both adjacent modes are admissible
// (λ_n = 0 with a_n = 0; ‖λ_t‖ = μλ_n with a_t = 0). The crossing direction decides: a contact
// whose lift-off guard fired is opened unless that makes it penetrate (a_n < 0), and one whose
// stick→slip guard fired slips opposite to its last stick force.
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/constrained_flow.hpp"
#include "lib/engines/event_driven/event_driven_options.hpp"

namespace impactbench::engines::event_driven {

struct ModeCandidate {
  const model::Contact<double>* contact = nullptr;
  enum class Hint { kNone, kPreferOpen, kForceSlip } hint = Hint::kNone;
  Eigen::VectorXd forced_slip_direction;  ///< kForceSlip: the slip direction s (unit, size d)
};

struct ModeDecision {
  ContactMode mode = ContactMode::kOpen;
  Eigen::VectorXd slip_reference;  ///< slip: s (unit, size d)
  double lambda_n = 0.0;
  Eigen::VectorXd lambda_t;
  double accel_n = 0.0;
  Eigen::VectorXd accel_t;
};

struct ModeConsistencyResult {
  std::vector<ModeDecision> decisions;  ///< aligned with the candidates
  bool ok = true;
  std::string message;
  /// Acceleration-level LCPs solved by enumeration after the LCP solver failed.
  int enumerated = 0;
};

ModeConsistencyResult make_modes_consistent(const DynamicsAtState& dynamics,
                                            const Eigen::VectorXd& v,
                                            const std::vector<ModeCandidate>& candidates,
                                            const EventDrivenOptions& options);

}  // namespace impactbench::engines::event_driven
