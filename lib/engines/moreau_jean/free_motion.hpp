#pragma once
// The smooth part of a Moreau–Jean step: the velocity the system would reach without contact
// impulses, v_free, and the inverse of the matrix that maps impulses to velocity changes
// (v_{k+1} = v_free + Â⁻¹ Jᵀ r).
//
// Explicit forces (θ-method with f evaluated at the θ-point): q_θ = q_k ⊕ θ h v_k and, with the
// damping matrix C = ∂H/∂v the system states in closed form (LagrangianSystem::damping_matrix;
// C = 0 when it states none), f(q_θ, v_θ) ≈ f(q_θ, v_k) − θ C (v_{k+1} − v_k) in
// M (v_{k+1} − v_k) = h f(q_θ, v_θ):
//     Â = M(q_θ) + hθ C,  v_free = v_k + h Â⁻¹ f(q_θ, v_k, t_k + θh).
// A damper evaluated at v_k alone would make the step first order; at v_θ (θ = 1/2) it is the
// midpoint rule, second order, and costs no extra evaluation of H.
// Linearly implicit forces (the standard Moreau–Jean linearisation, Acary–Brogliato 2008 §10):
// with f_{k+1} ≈ f_k − K (q_{k+1} − q_k) − C (v_{k+1} − v_k) and
// q_{k+1} − q_k = h (v_k + θ Δv) in θ M Δv = h (θ f_{k+1} + (1 − θ) f_k):
//     Â = M(q_k) + hθ C + h²θ² K,   v_free = v_k + Â⁻¹ (h f_k − h² θ K v_k),
// where f_k = S(q_k) u(t_k + θh) − H(q_k, v_k), K = ∂(H − S u)/∂q (along velocity directions,
// through integrate_position) and C = ∂(H − S u)/∂v.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "lib/engines/moreau_jean/moreau_jean_options.hpp"
#include "lib/model/lagrangian_system.hpp"

namespace impactbench::engines::moreau_jean {

struct FreeMotion {
  Eigen::SparseMatrix<double> inverse_iteration_matrix;  ///< Â⁻¹, nv × nv, block diagonal
  Eigen::VectorXd free_velocity;                         ///< v_free, nv
  /// Â⁻¹ = M⁻¹ kept by the caller (inverse_iteration_matrix is then not used), or null.
  const Eigen::SparseMatrix<double>* kept_inverse = nullptr;
  /// M(q_θ) when it was formed (explicit forces), kept for the next computation into this one.
  Eigen::SparseMatrix<double> mass_matrix;
  /// Scratch kept with it (explicit forces): q_θ, the smooth force f and h Â⁻¹ f.
  Eigen::VectorXd q_theta, force, velocity_change;
  /// ∂H/∂v at q_θ (explicit forces, a system with a damping matrix).
  Eigen::SparseMatrix<double> damping;

  const Eigen::SparseMatrix<double>& inverse() const {
    return kept_inverse != nullptr ? *kept_inverse : inverse_iteration_matrix;
  }
};

/// `input` is u(t_k + θh) (empty when the system has no inputs). `constant_mass_inverse`, if
/// given, keeps M⁻¹ across steps where Â = M is constant (explicit forces, no damping, and a
/// system whose M does not depend on q): formed into it when it is empty, reused after.
FreeMotion compute_free_motion(const model::LagrangianSystem<double>& system,
                               const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               const Eigen::VectorXd& input, double h,
                               const MoreauJeanOptions& options,
                               Eigen::SparseMatrix<double>* constant_mass_inverse = nullptr);
/// The same into `out`, reusing the storage of what was computed into it before (a caller that
/// keeps `out` from step to step forms M and Â⁻¹ in place).
void compute_free_motion(const model::LagrangianSystem<double>& system, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& v, const Eigen::VectorXd& input, double h,
                         const MoreauJeanOptions& options,
                         Eigen::SparseMatrix<double>* constant_mass_inverse, FreeMotion& out);

}  // namespace impactbench::engines::moreau_jean
