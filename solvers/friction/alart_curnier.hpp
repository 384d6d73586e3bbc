#pragma once
// Alart–Curnier function of one contact, the root-finding form of the contact and friction
// laws used by the semismooth Newton solvers (global and single-contact):
//   p = r − P u,  P = diag(ρ_n, ρ_t, ρ_t),
//   Φ_n = r_n − max(0, p_n),   Φ_t = r_t − Π_{disk μ max(0, p_n)}(p_t).
// Φ = 0 ⇔ 0 ≤ r_n ⊥ u_n ≥ 0 and r_t on the disk opposing u_t (B.16 with a fixed point).
// With dΦ = (I − F') dr + F' P du, F' ∈ ∂Π at p, a generalised Jacobian with respect to r is
//   ∂Φ/∂r = A + B ∂u/∂r,  A = I − F',  B = F' P.
#include <algorithm>
#include <type_traits>

#include "solvers/friction/coulomb_cone.hpp"

namespace impactbench::solvers {

struct AlartCurnierParameters {
  double rho_n = 1.0;  ///< normal step, 1 / W_nn
  double rho_t = 1.0;  ///< tangential step (one scalar, so the disk projection stays isotropic)
};

/// ρ from the diagonal block of W: ρ_n = 1/W_nn, ρ_t = 1/mean(W_tt). Requires W_nn > 0.
/// `Matrix`: LocalMatrix, or a fixed-size square matrix.
template <typename Matrix>
AlartCurnierParameters alart_curnier_parameters(const Matrix& diagonal_block) {
  const int d = static_cast<int>(diagonal_block.rows());
  AlartCurnierParameters rho;
  rho.rho_n = 1.0 / diagonal_block(0, 0);
  const double tangential = diagonal_block.diagonal().tail(d - 1).mean();
  rho.rho_t = tangential > 0.0 ? 1.0 / tangential : rho.rho_n;
  return rho;
}

/// Φ for one contact; when `a` and `b` are given, also the Jacobian blocks A and B.
LocalVector alart_curnier(double mu, const AlartCurnierParameters& rho, const LocalVector& r,
                          const LocalVector& u, LocalMatrix* a = nullptr, LocalMatrix* b = nullptr);

namespace alart_curnier_detail {

/// The function above for `Vector` LocalVector (Matrix LocalMatrix), or of fixed size D with
/// `Matrix` D × D: the same arithmetic, the fixed size without runtime sizes or size checks
/// (the spatial single-contact Newton runs it for every sliding contact of every sweep).
template <typename Vector, typename Matrix>
Vector evaluate(double mu, const AlartCurnierParameters& rho, const Vector& r, const Vector& u,
                Matrix* a, Matrix* b) {
  constexpr int kTangent = kTangentSize<Vector>;
  constexpr bool kFixed = kTangent != Eigen::Dynamic;
  using Tangent = std::conditional_t<kFixed, Eigen::Matrix<double, kTangent, 1>, LocalVector>;
  using TangentMatrix =
      std::conditional_t<kFixed, Eigen::Matrix<double, kTangent, kTangent>, LocalMatrix>;
  const int d = static_cast<int>(r.size());
  const int t = d - 1;
  const double p_n = r(0) - rho.rho_n * u(0);
  const Tangent p_t =
      r.template segment<kTangent>(1, t) - rho.rho_t * u.template segment<kTangent>(1, t);
  const double radius = mu * std::max(0.0, p_n);
  Vector phi(d);
  phi(0) = r(0) - std::max(0.0, p_n);
  phi.template segment<kTangent>(1, t) =
      r.template segment<kTangent>(1, t) - project_on_disk_of(radius, p_t);
  if (a == nullptr || b == nullptr) return phi;

  // F' = ∂Π/∂p, row n then rows t (see the header's top).
  Matrix projection_derivative = Matrix::Zero(d, d);
  if (p_n > 0.0) projection_derivative(0, 0) = 1.0;
  const double length = p_t.norm();
  if (length <= radius && radius > 0.0) {
    projection_derivative.template block<kTangent, kTangent>(1, 1, t, t).setIdentity();
  } else if (length > 0.0) {
    const Tangent direction = p_t / length;
    projection_derivative.template block<kTangent, kTangent>(1, 1, t, t) =
        (radius / length) * (TangentMatrix::Identity(t, t) - direction * direction.transpose());
    if (p_n > 0.0) projection_derivative.template block<kTangent, 1>(1, 0, t, 1) = mu * direction;
  }
  *a = Matrix::Identity(d, d) - projection_derivative;
  Vector steps(d);
  steps(0) = rho.rho_n;
  steps.template segment<kTangent>(1, t).setConstant(rho.rho_t);
  *b = projection_derivative * steps.asDiagonal();
  return phi;
}

}  // namespace alart_curnier_detail

}  // namespace impactbench::solvers
