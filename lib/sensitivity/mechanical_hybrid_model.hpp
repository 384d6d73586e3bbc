#pragma once
// The hybrid model of a planar Lagrangian system with unilateral contacts (source B.3), for the
// sensitivity module. State x = (q, v), input u.
//
// Flow of a mode (B.36–B.41). With the closed contacts' constraint rows J (w_nᵀ per closed
// contact, plus W_tᵀ when sticking), force columns C (w_n − μ s W_t per slipping contact, i.e.
// slip friction λ_t = −μ λ_n s folded in; w_n and W_t per sticking contact) and drifts d
// (ẇ_nᵀv, Ẇ_tᵀv), the accelerations keep the closed contacts closed (c_1/c_2: ζ̇ = J v̇ + d = 0):
//     M v̇ = S u − H + C λ,    (J M⁻¹ C) λ = −d − J M⁻¹ (S u − H),
//     f_s(x, u) = (q̇, v̇) = (N(q) v, M⁻¹ (S u − H + C λ)).
// λ(x, u) therefore depends on the input, and so do the lift-off and stick→slip guards.
//
// Impact of contact i (B.19–B.24 generalised to Newton restitution). The same rows/columns for
// the contacts closed after the impact, the impacting contact's normal row with target
// ζ_n,i⁺ = −e_i ζ_n,i⁻ (and, if it bounces open with μ > 0, the slip column with the direction
// of ζ_t⁻), all other rows with target 0:
//     Λ = (J M⁻¹ C)⁻¹ (target − J v⁻),   v⁺ = v⁻ + M⁻¹ C Λ,   q⁺ = q⁻.
// Mode changes without impact (lift-off, stick↔slip) keep the state: g = identity.
//
// All Jacobians come from forward-mode AD through the system templated on the scalar
// (Eigen::AutoDiffScalar<Eigen::VectorXd>), so the model must be given in both scalars. The
// contacts are those find_contacts lists with a 1 km margin (small systems: a fixed list),
// indexed in its order. Planar (tangent_dim() == 1) and spatial (tangent_dim() == 2) systems:
// spatial slip uses the turning direction ε(ζ_t) (hybrid_mode.hpp), whose derivative the AD
// Jacobians carry; a spatial slip impulse (Γ < 0) is the impulse-level Coulomb law, Λ_t
// opposite to ζ_t⁺, as the engine solves it, with its direction differentiated implicitly. The
// state keeps the quaternions (nq + nv entries; the flow preserves their norm, so perturbations
// tangent to the unit sphere stay tangent); tangent_basis / tangent_projection convert to the
// tangent coordinates (3 per orientation) in which gains are reported.
//
// Redundant closed contacts (two sticking bottom corners of a box on a line have equal tangent
// rows): J M⁻¹ C is singular but the system consistent. The solves then use a maximal set of
// independent rows (chosen on the values) and the least-norm multipliers; the accelerations are
// unique and so are their derivatives along the constraint manifold (where perturbations live).
// The tangential forces of redundant sticking contacts are split in proportion to their normal
// forces, so a redundant group reaches its friction cones at one instant, when the total force
// leaves the total cone — the rigid body's slip condition (see mode_flow in the .cpp).
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "lib/model/autodiff.hpp"
#include "lib/model/lagrangian_system.hpp"
#include "lib/sensitivity/hybrid_model.hpp"

namespace impactbench::sensitivity {

/// The models' one forward-mode AD scalar (lib/model/autodiff.hpp).
using model::AutoDiff;

/// Constrained accelerations and multipliers of one mode at one state (for inspection/tests).
struct ModeForces {
  Eigen::VectorXd v_dot;
  Eigen::VectorXd lambda_n;  ///< per contact, 0 when open
  Eigen::MatrixXd lambda_t;  ///< per contact (row) its d tangential components, 0 when open
};

class MechanicalHybridModel final : public HybridModel {
 public:
  /// Both systems must describe the same model and outlive this object. With
  /// `parameter_states` the friction coefficient μ and the restitution e (one material for all
  /// contacts) are appended to the state as two entries with zero flow, x = (q, v, μ, e), so
  /// that the gains' last two columns are the sensitivities to μ and e. Throws
  /// std::invalid_argument for systems it cannot linearise or inconsistent sizes.
  MechanicalHybridModel(const model::LagrangianSystem<double>& system,
                        const model::LagrangianSystem<AutoDiff>& system_ad,
                        bool parameter_states = false);

  int state_size() const override { return nq_ + nv_ + np_; }
  int num_parameters() const { return np_; }
  /// x = (q, v) with the parameter values appended when they are states.
  Eigen::VectorXd state(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
  int input_size() const override { return nu_; }
  int num_contacts() const override { return num_contacts_; }
  int num_positions() const { return nq_; }
  int num_velocities() const { return nv_; }

  Eigen::VectorXd flow(const HybridMode& mode, const Eigen::VectorXd& x,
                       const Eigen::VectorXd& u) const override;
  FlowLinearisation linearise_flow(const HybridMode& mode, const Eigen::VectorXd& x,
                                   const Eigen::VectorXd& u) const override;
  GuardLinearisation linearise_guard(const HybridMode& mode, const MicroEvent& event,
                                     const Eigen::VectorXd& x,
                                     const Eigen::VectorXd& u) const override;
  ResetLinearisation linearise_reset(const HybridMode& mode, const MicroEvent& event,
                                     const Eigen::VectorXd& x) const override;
  Eigen::MatrixXd mode_constraint_rows(const HybridMode& mode,
                                       const Eigen::VectorXd& x) const override;

  /// γ of `event` in `mode` (double only; the reference simulators' root functions).
  double guard_value(const HybridMode& mode, const MicroEvent& event, const Eigen::VectorXd& x,
                     const Eigen::VectorXd& u) const;
  /// g(x) of `event` from `mode` (double only).
  Eigen::VectorXd reset(const HybridMode& mode, const MicroEvent& event,
                        const Eigen::VectorXd& x) const;
  ModeForces mode_forces(const HybridMode& mode, const Eigen::VectorXd& x,
                         const Eigen::VectorXd& u) const;
  /// Gap and relative velocities (ζ_n, ζ_t) of every contact.
  Eigen::VectorXd gaps(const Eigen::VectorXd& x) const;
  Eigen::MatrixXd relative_velocities(const Eigen::VectorXd& x) const;  ///< num_contacts × (1+d)

  /// Tangent coordinates of perturbations (2 nv entries, then μ and e if they are states): (δp, δv)
  /// for planar systems, and per spatial body (δc, δθ, δv, δω) with δθ the rotation vector in the
  /// WORLD frame, the perturbed orientation being exp(½ (0, ε δθ)) ⊗ quat (left product, like the
  /// world-frame ω of the kinematics). tangent_basis(x) = blockdiag(N(q), I) maps them to state
  /// perturbations (δquat = ½ (0, δθ) ⊗ quat); tangent_projection(x) is its left inverse. Both are
  /// the identity for planar systems.
  Eigen::MatrixXd tangent_basis(const Eigen::VectorXd& x) const override;
  Eigen::MatrixXd tangent_projection(const Eigen::VectorXd& x) const override;
  /// True when positions carry unit quaternions (nq > nv).
  bool has_tangent_coordinates() const override { return nq_ != nv_; }
  bool slip_direction_turns() const override { return system_.tangent_dim() > 1; }

 private:
  void check(const HybridMode& mode, const Eigen::VectorXd& x, const Eigen::VectorXd* u) const;
  void check_state(const Eigen::VectorXd& x) const;
  Eigen::MatrixXd position_rate_matrix(const Eigen::VectorXd& x) const;  ///< N(q), nq × nv

  const model::LagrangianSystem<double>& system_;
  const model::LagrangianSystem<AutoDiff>& system_ad_;
  int nq_ = 0, nv_ = 0, nu_ = 0, num_contacts_ = 0;
  int np_ = 0;                                                  ///< parameter states (0 or 2)
  Eigen::Vector2d parameter_values_ = Eigen::Vector2d::Zero();  ///< μ, e
};

}  // namespace impactbench::sensitivity
