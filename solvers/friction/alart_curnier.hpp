#pragma once
// Alart–Curnier function of one contact, the root-finding form of the contact and friction
// laws used by the semismooth Newton solvers (global and single-contact):
//   p = r − P u,  P = diag(ρ_n, ρ_t, ρ_t),
//   Φ_n = r_n − max(0, p_n),   Φ_t = r_t − Π_{disk μ max(0, p_n)}(p_t).
// Φ = 0 ⇔ 0 ≤ r_n ⊥ u_n ≥ 0 and r_t on the disk opposing u_t (B.16 with a fixed point).
// With dΦ = (I − F') dr + F' P du, F' ∈ ∂Π at p, a generalised Jacobian with respect to r is
//   ∂Φ/∂r = A + B ∂u/∂r,  A = I − F',  B = F' P.
#include "solvers/friction/coulomb_cone.hpp"

namespace impactbench::solvers {

struct AlartCurnierParameters {
  double rho_n = 1.0;  ///< normal step, 1 / W_nn
  double rho_t = 1.0;  ///< tangential step (one scalar, so the disk projection stays isotropic)
};

/// ρ from the diagonal block of W: ρ_n = 1/W_nn, ρ_t = 1/mean(W_tt). Requires W_nn > 0.
AlartCurnierParameters alart_curnier_parameters(const LocalMatrix& diagonal_block);

/// Φ for one contact; when `a` and `b` are given, also the Jacobian blocks A and B.
LocalVector alart_curnier(double mu, const AlartCurnierParameters& rho, const LocalVector& r,
                          const LocalVector& u, LocalMatrix* a = nullptr, LocalMatrix* b = nullptr);

}  // namespace impactbench::solvers
