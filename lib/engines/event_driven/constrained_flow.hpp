#pragma once
// The smooth flow of one hybrid mode (B.31–B.41): with the contact forces of the closed contacts
// as unknowns,
//     M v̇ = S u − H + Σ_closed (g_i λ_n,i + [stick] W_t,i λ_t,i),
//     w_n,iᵀ v̇ + ẇ_n,iᵀ v = 0                (every closed contact, B.36/B.40)
//     W_t,iᵀ v̇ + Ẇ_t,iᵀ v = 0                (stick, B.41)
// where g_i = w_n,i for stick and g_i = w_n,i − μ_i W_t,i s_i for slip, which is B.37
// (λ_t = −μ λ_n s with s the slip direction) folded into the normal column.
// Eliminating v̇ gives the Delassus system D λ = b with D = A M⁻¹ G (not symmetric with slip).
//
// Redundant constraints (a box resting on two corners: two equal tangential rows) leave λ
// undetermined; v̇ is still unique. Of all solutions we pick the one that spreads each
// tangential force in proportion to μ_i λ_n,i (minimising Σ ‖λ_t,i‖² / (μ_i λ_n,i)), so that
// the stick→slip guards of a rigid body's contacts cross together, when the body as a whole
// reaches the friction limit, instead of at an arbitrary split.
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/QR>

#include "lib/engines/event_driven/dynamics_at_state.hpp"
#include "lib/engines/event_driven/event_driven_options.hpp"
#include "lib/engines/event_driven/event_types.hpp"
#include "lib/model/lagrangian_system.hpp"

namespace impactbench::engines::event_driven {

/// Dense local frame of one contact: J = [w_n W_t] (nv x (1+d)) and the drift [ẇ_nᵀv; Ẇ_tᵀv].
struct ContactFrame {
  Eigen::MatrixXd J;
  Eigen::VectorXd drift;
  static ContactFrame of(const model::Contact<double>& contact, int nv);
  /// The frame of `contact`, in this frame's storage.
  void assign(const model::Contact<double>& contact, int nv);
};

/// A contact the flow treats as closed, with its mode and slip direction reference.
struct ClosedContact {
  const model::Contact<double>* contact = nullptr;
  ContactMode mode = ContactMode::kStick;
  Eigen::VectorXd slip_reference;  ///< s_ref, unit, size d (slip only)
};

/// The slip direction used in the force: in the plane s_ref = ±1, in space
/// model::smoothed_slip_direction (lib/model/slip_direction.hpp) with `blend_speed` the
/// velocity tolerance.
Eigen::VectorXd slip_direction(const Eigen::VectorXd& zeta_t, const Eigen::VectorXd& reference,
                               double blend_speed);

struct ContactForce {
  double lambda_n = 0.0;
  Eigen::VectorXd lambda_t;  ///< size d (the slip friction −μ λ_n s for slip)
};

struct FlowSolution {
  Eigen::VectorXd vdot;
  std::vector<ContactForce> forces;  ///< aligned with the closed contacts
  bool ok = true;                    ///< false: D λ = b has no solution (inconsistent modes)
};

/// The storage of solve_constrained_flow, kept by a caller that solves at every right-hand
/// side (no allocation per solve once sized).
struct FlowWorkspace {
  ContactFrame frame;
  Eigen::MatrixXd A, G, MinvG, D;
  Eigen::VectorXd drift, MinvF, b, lambda, zeta_t;
  std::vector<Eigen::VectorXd> slip_dirs;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
};

/// The flow of the closed contacts' modes at one state. Uses options.flow_rank_threshold,
/// flow_residual_tolerance and friction_capacity_floor.
FlowSolution solve_constrained_flow(const DynamicsAtState& dynamics, const Eigen::VectorXd& v,
                                    const std::vector<ClosedContact>& closed,
                                    const EventDrivenOptions& options);
/// The same into `out`, with the storage of `work` and `out` kept.
void solve_constrained_flow(const DynamicsAtState& dynamics, const Eigen::VectorXd& v,
                            const std::vector<ClosedContact>& closed,
                            const EventDrivenOptions& options, FlowWorkspace& work,
                            FlowSolution& out);

}  // namespace impactbench::engines::event_driven
