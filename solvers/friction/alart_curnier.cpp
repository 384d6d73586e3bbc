#include "solvers/friction/alart_curnier.hpp"

#include <algorithm>

namespace impactbench::solvers {

AlartCurnierParameters alart_curnier_parameters(const LocalMatrix& diagonal_block) {
  const int d = static_cast<int>(diagonal_block.rows());
  AlartCurnierParameters rho;
  rho.rho_n = 1.0 / diagonal_block(0, 0);
  const double tangential = diagonal_block.diagonal().tail(d - 1).mean();
  rho.rho_t = tangential > 0.0 ? 1.0 / tangential : rho.rho_n;
  return rho;
}

LocalVector alart_curnier(double mu, const AlartCurnierParameters& rho, const LocalVector& r,
                          const LocalVector& u, LocalMatrix* a, LocalMatrix* b) {
  const int d = static_cast<int>(r.size());
  const int t = d - 1;
  const double p_n = r(0) - rho.rho_n * u(0);
  const LocalVector p_t = r.tail(t) - rho.rho_t * u.tail(t);
  const double radius = mu * std::max(0.0, p_n);
  LocalVector phi(d);
  phi(0) = r(0) - std::max(0.0, p_n);
  phi.tail(t) = r.tail(t) - project_on_disk(radius, p_t);
  if (a == nullptr || b == nullptr) return phi;

  // F' = ∂Π/∂p, row n then rows t (see header).
  LocalMatrix projection_derivative = LocalMatrix::Zero(d, d);
  if (p_n > 0.0) projection_derivative(0, 0) = 1.0;
  const double length = p_t.norm();
  if (length <= radius && radius > 0.0) {
    projection_derivative.bottomRightCorner(t, t).setIdentity();
  } else if (length > 0.0) {
    const LocalVector direction = p_t / length;
    projection_derivative.bottomRightCorner(t, t) =
        (radius / length) * (LocalMatrix::Identity(t, t) - direction * direction.transpose());
    if (p_n > 0.0) projection_derivative.bottomLeftCorner(t, 1) = mu * direction;
  }
  *a = LocalMatrix::Identity(d, d) - projection_derivative;
  LocalVector steps(d);
  steps(0) = rho.rho_n;
  steps.tail(t).setConstant(rho.rho_t);
  *b = projection_derivative * steps.asDiagonal();
  return phi;
}

}  // namespace impactbench::solvers
