#pragma once
// Jump gains of one micro event (source C.1, C.37–C.39), derived here for a guard that depends
// on the input.
//
// Derivation. A perturbed trajectory x_ε(t) = α(t) + ε z(t) + o(ε), under the input
// u_ε(t) = μ(t) + ε v(t), meets the guard γ(x, u) = 0 at t_ε = τ + ε Δ instead of τ. Before the
// event (extending α⁻ and z⁻ a little past τ):
//     x_ε⁻(t_ε) = α⁻(τ) + ε (f⁻ Δ + z⁻) + o(ε),   u_ε(t_ε) = μ(τ) + ε (μ̇ Δ + v) + o(ε),
// with f⁻ = α̇⁻(τ). Expanding γ(x_ε⁻(t_ε), u_ε(t_ε)) = 0 to first order (C.21):
//     D_xγ (f⁻ Δ + z⁻) + D_uγ (μ̇ Δ + v) = 0
//  ⇒  Δ = a z⁻ + b v,   a = −D_xγ / γ̇,   b = −D_uγ / γ̇,   γ̇ = D_xγ f⁻ + D_uγ μ̇   (C.22, C.24, D.7).
// The state after the jump is g(x_ε⁻(t_ε)) = α⁺(τ) + ε D_xg (f⁻ Δ + z⁻) + o(ε) (g independent of
// u and t, C.27), and the post-event trajectory extended back to τ is
//     x_ε⁺(t_ε) = α⁺(τ) + ε (f⁺ Δ + z⁺) + o(ε),   f⁺ = f_{s⁺}(α⁺(τ), μ(τ)).
// Equating the two:
//     z⁺ = D_xg z⁻ + (D_xg f⁻ − f⁺) Δ = G_z z⁻ + G_v v,
//     G_z = D_xg + (f⁺ − D_xg f⁻) D_xγ / γ̇,     G_v = (f⁺ − D_xg f⁻) D_uγ / γ̇     (C.37, C.38).
// With D_uγ = 0 this is the classical saltation matrix. Guards are positive inside their mode,
// so a transversal crossing has γ̇ < 0; a (near) tangential crossing has no first-order gain and
// is rejected. Note that for events whose vector field is continuous with g = identity (lift-off
// at λ_n = 0, stick→slip at |λ_t| = μλ_n) the gains reduce to G_z = I, G_v = 0 although Δ
// depends on v: the input-dependent guard shifts the switching time, not the state.
#include <Eigen/Core>

#include "lib/sensitivity/hybrid_model.hpp"

namespace impactbench::sensitivity {

struct JumpGain {
  Eigen::MatrixXd Gz;    ///< n × n
  Eigen::MatrixXd Gv;    ///< n × m
  Eigen::RowVectorXd a;  ///< Δ = a z⁻ + b v (D.7): the event-time shift per unit perturbation
  Eigen::RowVectorXd b;
  double guard_rate = 0.0;  ///< γ̇⁻ (< 0)
};

/// C.37/C.38 from the nominal quantities at the event. Throws std::runtime_error if the crossing
/// is not transversal (γ̇ ≥ −1e-12 × scale) and std::invalid_argument for size mismatches.
JumpGain compute_jump_gain(const Eigen::VectorXd& f_minus, const Eigen::VectorXd& f_plus,
                           const Eigen::MatrixXd& reset_jacobian, const GuardLinearisation& guard,
                           const Eigen::VectorXd& input_rate);

/// One micro event linearised at the nominal: states, modes, vector fields and gains.
struct MicroEventLinearisation {
  MicroEvent event;
  HybridMode mode_before, mode_after;
  Eigen::VectorXd x_minus, x_plus, f_minus, f_plus;
  GuardLinearisation guard;
  JumpGain gain;
  /// True when this micro event switched together with the previous one of its path because
  /// their guards coincide to first order (see ConewiseJumpGain): its own gain is the identity
  /// and its mode change is already part of the previous micro event's.
  bool joined = false;
};

/// Evaluates the model at (x_minus, u) and forms the gains; u_rate = μ̇(τ).
MicroEventLinearisation linearise_micro_event(const HybridModel& model, const HybridMode& mode,
                                              const MicroEvent& event,
                                              const Eigen::VectorXd& x_minus,
                                              const Eigen::VectorXd& u,
                                              const Eigen::VectorXd& u_rate);

}  // namespace impactbench::sensitivity
