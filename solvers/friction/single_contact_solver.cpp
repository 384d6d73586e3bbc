#include "solvers/friction/single_contact_solver.hpp"

#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "solvers/friction/alart_curnier.hpp"

namespace impactbench::solvers {
namespace {

constexpr double kRoundoff = 1e-13;  // relative slack when testing a case's consistency

bool inside_cone(double mu, const LocalVector& r, double scale) {
  return r(0) >= -kRoundoff * scale && r.tail(r.size() - 1).norm() <= mu * r(0) + kRoundoff * scale;
}

/// Planar slip with r_t = −σ μ r_n (σ = sign of the sliding velocity u_t):
///   u_n = (A_nn − σ μ A_nt) r_n + b_n = 0  ⇒  r_n = −b_n / (A_nn − σ μ A_nt),
///   consistent if r_n ≥ 0 and σ u_t ≥ 0 with u_t = (A_tn − σ μ A_tt) r_n + b_t.
bool planar_slip(const LocalMatrix& a, const LocalVector& b, double mu, double sigma, double scale,
                 LocalVector& r) {
  const double denominator = a(0, 0) - sigma * mu * a(0, 1);
  if (denominator <= 0.0) return false;
  const double r_n = -b(0) / denominator;
  const double u_t = (a(1, 0) - sigma * mu * a(1, 1)) * r_n + b(1);
  if (r_n < 0.0 || sigma * u_t < -kRoundoff * scale) return false;
  r(0) = r_n;
  r(1) = -sigma * mu * r_n;
  return true;
}

/// Alart–Curnier Newton for one contact, Armijo backtracking on ½‖Φ‖², then the projected
/// fixed point r ← r − Φ(r) if Newton stops short. Returns whether ‖Φ‖ reached roundoff.
bool alart_curnier_newton(const LocalMatrix& a, const LocalVector& b, double mu, LocalVector& r) {
  const AlartCurnierParameters rho = alart_curnier_parameters(a);
  const double target =
      1e-15 * (rho.rho_n * b.norm() + r.norm()) + std::numeric_limits<double>::min();
  const int d = static_cast<int>(r.size());
  LocalMatrix block_a(d, d);
  LocalMatrix block_b(d, d);
  LocalVector phi = alart_curnier(mu, rho, r, a * r + b, &block_a, &block_b);
  double merit = phi.squaredNorm();
  for (int iteration = 0; iteration < 60 && std::sqrt(merit) > target; ++iteration) {
    const LocalMatrix jacobian = block_a + block_b * a;
    const LocalVector step = -jacobian.fullPivLu().solve(phi);
    if (!step.allFinite()) break;
    double alpha = 1.0;
    bool accepted = false;
    for (int halving = 0; halving < 30; ++halving, alpha *= 0.5) {
      const LocalVector trial = r + alpha * step;
      const LocalVector trial_phi = alart_curnier(mu, rho, trial, a * trial + b);
      if (trial_phi.squaredNorm() <= (1.0 - 1e-4 * alpha) * merit) {
        r = trial;
        accepted = true;
        break;
      }
    }
    if (!accepted) break;
    phi = alart_curnier(mu, rho, r, a * r + b, &block_a, &block_b);
    merit = phi.squaredNorm();
  }
  for (int iteration = 0; iteration < 2000 && std::sqrt(merit) > target; ++iteration) {
    r -= phi;
    phi = alart_curnier(mu, rho, r, a * r + b);
    merit = phi.squaredNorm();
  }
  return std::sqrt(merit) <= 1e3 * target;
}

}  // namespace

bool solve_single_contact(const LocalMatrix& a, const LocalVector& b, double mu, LocalVector& r) {
  const int d = static_cast<int>(b.size());
  if (b(0) >= 0.0) {  // open: separating without any impulse
    r.setZero(d);
    return true;
  }
  const double scale = b.norm() / a(0, 0);
  const auto lu = a.fullPivLu();
  if (lu.isInvertible()) {
    const LocalVector stick = lu.solve(-b);
    if (inside_cone(mu, stick, scale)) {
      r = stick;
      return true;
    }
    if (d == 3 && !inside_cone(mu, r, scale)) r = project_on_coulomb_cone(mu, stick);
  }
  if (d == 2) {
    LocalVector slip(2);
    if (planar_slip(a, b, mu, +1.0, scale, slip) || planar_slip(a, b, mu, -1.0, scale, slip)) {
      r = slip;
      return true;
    }
  }
  if (r.size() != d || !r.allFinite() || r(0) <= 0.0) {
    r.setZero(d);
    r(0) = -b(0) / a(0, 0);
  }
  return alart_curnier_newton(a, b, mu, r);
}

}  // namespace impactbench::solvers
