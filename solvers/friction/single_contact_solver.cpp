#include "solvers/friction/single_contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solvers/friction/alart_curnier.hpp"

namespace impactbench::solvers {
namespace {

constexpr double kRoundoff = 1e-13;  // relative slack when testing a case's consistency

/// det A of a 2 × 2 A into `det`; false when A is singular to working precision (solve_small's
/// rank test for n = 2).
[[gnu::always_inline]] inline bool invertible_2x2(double a00, double a01, double a10, double a11,
                                                  double& det) {
  const double largest =
      std::max(std::max(std::abs(a00), std::abs(a10)), std::max(std::abs(a01), std::abs(a11)));
  det = a00 * a11 - a01 * a10;
  return std::abs(det) > 2.0 * std::numeric_limits<double>::epsilon() * largest * largest;
}
[[gnu::always_inline]] inline bool invertible_2x2(const LocalMatrix& a, double& det) {
  return invertible_2x2(a(0, 0), a(0, 1), a(1, 0), a(1, 1), det);
}

/// The 2 × 2 case of solve_small in scalars (the planar sweeps solve one per contact).
[[gnu::always_inline]] inline bool solve_2x2(const LocalMatrix& a, double y0, double y1, double& x0,
                                             double& x1) {
  double det = 0.0;
  if (!invertible_2x2(a, det)) return false;
  x0 = (a(1, 1) * y0 - a(0, 1) * y1) / det;
  x1 = (a(0, 0) * y1 - a(1, 0) * y0) / det;
  return true;
}

/// The cofactors of a 3 × 3 A and det A, for x = A⁻¹ y by Cramer's rule (cramer_solve_3x3);
/// false when A is singular to working precision, |det A| ≤ 3 ε max|A_ij|³ with `largest` =
/// max|A_ij| (the rank test of a pivoted LU, with the largest entry bounding the pivots).
template <typename Matrix>
bool cramer_factors_3x3(const Matrix& a, double largest, Eigen::Matrix3d& cofactor, double& det) {
  const Eigen::Matrix3d m = a;
  cofactor(0, 0) = m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1);
  cofactor(0, 1) = m(1, 2) * m(2, 0) - m(1, 0) * m(2, 2);
  cofactor(0, 2) = m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0);
  cofactor(1, 0) = m(0, 2) * m(2, 1) - m(0, 1) * m(2, 2);
  cofactor(1, 1) = m(0, 0) * m(2, 2) - m(0, 2) * m(2, 0);
  cofactor(1, 2) = m(0, 1) * m(2, 0) - m(0, 0) * m(2, 1);
  cofactor(2, 0) = m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1);
  cofactor(2, 1) = m(0, 2) * m(1, 0) - m(0, 0) * m(1, 2);
  cofactor(2, 2) = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  det = m.row(0).dot(cofactor.row(0));
  const double eps = std::numeric_limits<double>::epsilon();
  return std::abs(det) > 3.0 * eps * largest * largest * largest;
}

/// x = A⁻¹ y from cramer_factors_3x3's cofactors and determinant.
template <typename Vector>
Eigen::Vector3d cramer_solve_3x3(const Eigen::Matrix3d& cofactor, double det, const Vector& y) {
  return cofactor.transpose() * Eigen::Vector3d(y) / det;
}

/// x = A⁻¹ y for A of size 2 or 3 by cofactors (Cramer's rule): a fixed cost, no pivoting
/// search. False when A is singular to working precision, |det A| ≤ n ε max|A_ij|ⁿ (the rank
/// test of a pivoted LU, with the largest entry bounding the pivots). `Matrix`, `Vector`:
/// LocalMatrix and LocalVector, or of fixed size 3.
template <typename Matrix, typename Vector>
bool solve_small(const Matrix& a, const Vector& y, Vector& x) {
  const int n = static_cast<int>(a.rows());
  x.resize(n);
  const double largest = a.cwiseAbs().maxCoeff();
  if constexpr (Matrix::RowsAtCompileTime == Eigen::Dynamic) {
    if (n == 2) return solve_2x2(a, y(0), y(1), x(0), x(1));
    if (n == 1) {
      if (!(std::abs(a(0, 0)) > 0.0)) return false;
      x(0) = y(0) / a(0, 0);
      return true;
    }
  }
  Eigen::Matrix3d cofactor;
  double det = 0.0;
  if (!cramer_factors_3x3(a, largest, cofactor, det)) return false;
  x = cramer_solve_3x3(cofactor, det, y);
  return true;
}

/// r_n ≥ 0 and ‖r_t‖ ≤ μ r_n, both up to round-off relative to `scale`.
bool inside_cone(double mu, double r_n, double r_t_norm, double scale) {
  return r_n >= -kRoundoff * scale && r_t_norm <= mu * r_n + kRoundoff * scale;
}

template <typename Vector>
bool inside_cone(double mu, const Vector& r, double scale) {
  return inside_cone(mu, r(0), r.template segment<kTangentSize<Vector>>(1, r.size() - 1).norm(),
                     scale);
}

/// Planar slip with r_t = −σ μ r_n (σ = sign of the sliding velocity u_t):
///   u_n = (A_nn − σ μ A_nt) r_n + b_n = 0  ⇒  r_n = −b_n / (A_nn − σ μ A_nt),
///   consistent if r_n ≥ 0 and σ u_t ≥ 0 with u_t = (A_tn − σ μ A_tt) r_n + b_t.
bool planar_slip(const LocalMatrix& a, double b_n, double b_t, double mu, double sigma,
                 double scale, double& r_n, double& r_t) {
  const double denominator = a(0, 0) - sigma * mu * a(0, 1);
  if (denominator <= 0.0) return false;
  const double slip_n = -b_n / denominator;
  const double u_t = (a(1, 0) - sigma * mu * a(1, 1)) * slip_n + b_t;
  if (slip_n < 0.0 || sigma * u_t < -kRoundoff * scale) return false;
  r_n = slip_n;
  r_t = -sigma * mu * slip_n;
  return true;
}

/// Alart–Curnier Newton for one contact, Armijo backtracking on ½‖Φ‖², then the projected
/// fixed point r ← r − Φ(r) if Newton stops short. Returns whether ‖Φ‖ reached roundoff.
/// `Vector`, `Matrix` as for solve_small.
template <typename Vector, typename Matrix>
bool alart_curnier_newton(const Matrix& a, const Vector& b, double mu, Vector& r) {
  const AlartCurnierParameters rho = alart_curnier_parameters(a);
  // Φ at `at`, with the Jacobian blocks when asked for.
  const auto phi_at = [&](const Vector& at, Matrix* block_a, Matrix* block_b) {
    return alart_curnier_detail::evaluate<Vector, Matrix>(mu, rho, at, a * at + b, block_a,
                                                          block_b);
  };
  const double target =
      1e-15 * (rho.rho_n * b.norm() + r.norm()) + std::numeric_limits<double>::min();
  const int d = static_cast<int>(r.size());
  Matrix block_a(d, d);
  Matrix block_b(d, d);
  Vector phi = phi_at(r, &block_a, &block_b);
  double merit = phi.squaredNorm();
  for (int iteration = 0; iteration < 60 && std::sqrt(merit) > target; ++iteration) {
    const Matrix jacobian = block_a + block_b * a;
    Vector step;
    if (!solve_small<Matrix, Vector>(jacobian, -phi, step) || !step.allFinite()) break;
    double alpha = 1.0;
    bool accepted = false;
    // Each trial forms the Jacobian blocks with Φ: the first trial is accepted far more often
    // than not, and the accepted one's Φ and blocks serve the next iteration as they are,
    // without evaluating Φ at the new r a second time.
    Matrix trial_a(d, d);
    Matrix trial_b(d, d);
    for (int halving = 0; halving < 30; ++halving, alpha *= 0.5) {
      const Vector trial = r + alpha * step;
      const Vector trial_phi = phi_at(trial, &trial_a, &trial_b);
      if (trial_phi.squaredNorm() <= (1.0 - 1e-4 * alpha) * merit) {
        r = trial;
        phi = trial_phi;
        block_a = trial_a;
        block_b = trial_b;
        accepted = true;
        break;
      }
    }
    if (!accepted) break;
    merit = phi.squaredNorm();
  }
  for (int iteration = 0; iteration < 2000 && std::sqrt(merit) > target; ++iteration) {
    r -= phi;
    phi = phi_at(r, nullptr, nullptr);
    merit = phi.squaredNorm();
  }
  return std::sqrt(merit) <= 1e3 * target;
}

// The last case, when no closed form is consistent: Alart–Curnier Newton from r (from the
// normal-only impulse when r is not a usable start).
template <typename Vector, typename Matrix>
bool newton_fallback(const Matrix& a, const Vector& b, double mu, Vector& r) {
  const int d = static_cast<int>(b.size());
  if (r.size() != d || !r.allFinite() || r(0) <= 0.0) {
    r.setZero(d);
    r(0) = -b(0) / a(0, 0);
  }
  return alart_curnier_newton(a, b, mu, r);
}

// The planar cases' last resort from (r_n, r_t), in and out.
bool planar_newton_fallback(const LocalMatrix& a, double b_n, double b_t, double mu, double& r_n,
                            double& r_t) {
  LocalVector r(2);
  r << r_n, r_t;
  LocalVector b(2);
  b << b_n, b_t;
  const bool exact = newton_fallback(a, b, mu, r);
  r_n = r(0);
  r_t = r(1);
  return exact;
}

// The cases of a contact solved in vectors (not the planar scalars): open, stick, then the
// Newton fallback from r, or from the stick impulse projected on the cone when r is outside it.
// `Vector`, `Matrix` as for solve_small.
template <typename Matrix, typename Vector>
bool solve_single_contact_cases(const Matrix& a, const Vector& b, double mu, Vector& r) {
  const int d = static_cast<int>(b.size());
  if (b(0) >= 0.0) {  // open: separating without any impulse
    r.setZero(d);
    return true;
  }
  const double scale = b.norm() / a(0, 0);
  Vector stick;
  if (solve_small<Matrix, Vector>(a, -b, stick)) {
    if (inside_cone(mu, stick, scale)) {
      r = stick;
      return true;
    }
    if (!inside_cone(mu, r, scale)) r = project_on_coulomb_cone_of(mu, stick);
  }
  return newton_fallback(a, b, mu, r);
}

}  // namespace

bool solve_single_contact_planar(const LocalMatrix& a, double b_n, double b_t, double mu,
                                 double& r_n, double& r_t) {
  if (b_n >= 0.0) {  // open: separating without any impulse
    r_n = 0.0;
    r_t = 0.0;
    return true;
  }
  double stick_n = 0.0, stick_t = 0.0;
  const bool stick_solved = solve_2x2(a, -b_n, -b_t, stick_n, stick_t);
  // A stick impulse inside the cone without any slack is inside with it: the round-off slack
  // scale ≥ 0 (A_nn > 0) only widens the cone, so its square root and division wait for the
  // cases that need them (most contacts of a resting pile stick).
  if (stick_solved && a(0, 0) > 0.0 && stick_n >= 0.0 && std::abs(stick_t) <= mu * stick_n) {
    r_n = stick_n;
    r_t = stick_t;
    return true;
  }
  const double scale = std::sqrt(b_n * b_n + b_t * b_t) / a(0, 0);
  if (stick_solved && inside_cone(mu, stick_n, std::abs(stick_t), scale)) {
    r_n = stick_n;
    r_t = stick_t;
    return true;
  }
  if (planar_slip(a, b_n, b_t, mu, +1.0, scale, r_n, r_t) ||
      planar_slip(a, b_n, b_t, mu, -1.0, scale, r_n, r_t))
    return true;
  return planar_newton_fallback(a, b_n, b_t, mu, r_n, r_t);
}

PreparedPlanarContact prepare_planar_contact(const LocalMatrix& a, double mu) {
  const double entries[4] = {a(0, 0), a(0, 1), a(1, 0), a(1, 1)};
  return prepare_planar_contact(entries, mu);
}

PreparedPlanarContact prepare_planar_contact(const double (&a)[4], double mu) {
  PreparedPlanarContact p;
  for (int k = 0; k < 4; ++k) p.a[k] = a[k];
  p.mu = mu;
  p.inverse_a_nn = 1.0 / a[0];
  double det = 0.0;
  p.invertible = invertible_2x2(a[0], a[1], a[2], a[3], det);
  if (p.invertible) {
    const double inverse_det = 1.0 / det;
    p.inverse[0] = a[3] * inverse_det;
    p.inverse[1] = -a[1] * inverse_det;
    p.inverse[2] = -a[2] * inverse_det;
    p.inverse[3] = a[0] * inverse_det;
  }
  for (int k = 0; k < 2; ++k) {
    const double sigma = k == 0 ? 1.0 : -1.0;
    const double pivot = a[0] - sigma * mu * a[1];
    p.slips[k] = pivot > 0.0;
    p.inverse_pivot[k] = p.slips[k] ? 1.0 / pivot : 0.0;
    p.tangent_coefficient[k] = a[2] - sigma * mu * a[3];
  }
  return p;
}

bool solve_prepared_planar_contact_beyond_stick(const PreparedPlanarContact& p, double b_n,
                                                double b_t, double stick_n, double stick_t,
                                                double& r_n, double& r_t) {
  const double scale = std::sqrt(b_n * b_n + b_t * b_t) * p.inverse_a_nn;
  if (p.invertible && inside_cone(p.mu, stick_n, std::abs(stick_t), scale)) {
    r_n = stick_n;
    r_t = stick_t;
    return true;
  }
  for (int k = 0; k < 2; ++k) {  // slip with σ = +1, then −1 (planar_slip's cases)
    if (!p.slips[k]) continue;
    const double sigma = k == 0 ? 1.0 : -1.0;
    const double slip_n = -b_n * p.inverse_pivot[k];
    const double u_t = p.tangent_coefficient[k] * slip_n + b_t;
    if (slip_n < 0.0 || sigma * u_t < -kRoundoff * scale) continue;
    r_n = slip_n;
    r_t = -sigma * p.mu * slip_n;
    return true;
  }
  LocalMatrix a(2, 2);
  a << p.a[0], p.a[1], p.a[2], p.a[3];
  return planar_newton_fallback(a, b_n, b_t, p.mu, r_n, r_t);
}

bool solve_single_contact_spatial(const Eigen::Matrix3d& a, const Eigen::Vector3d& b, double mu,
                                  Eigen::Vector3d& r) {
  return solve_prepared_spatial_contact(prepare_spatial_contact(a, mu), b, r);
}

PreparedSpatialContact prepare_spatial_contact(const Eigen::Matrix3d& a, double mu) {
  PreparedSpatialContact p;
  p.a = a;
  p.mu = mu;
  p.invertible = cramer_factors_3x3(a, a.cwiseAbs().maxCoeff(), p.cofactor, p.det);
  return p;
}

bool solve_prepared_spatial_contact(const PreparedSpatialContact& prepared,
                                    const Eigen::Vector3d& b, Eigen::Vector3d& r) {
  const Eigen::Matrix3d& a = prepared.a;
  const double mu = prepared.mu;
  if (b(0) >= 0.0) {  // open: separating without any impulse
    r.setZero();
    return true;
  }
  if (prepared.invertible) {  // stick: A r = −b by Cramer's rule
    const Eigen::Vector3d stick = cramer_solve_3x3(prepared.cofactor, prepared.det, -b);
    // Inside the cone without the round-off slack is inside with it (the slack's scale is
    // ≥ 0): the scale's square root and division wait for the contacts that need them.
    const double stick_t = stick.segment<2>(1).norm();
    if (stick(0) >= 0.0 && stick_t <= mu * stick(0)) {
      r = stick;
      return true;
    }
    const double scale = b.norm() / a(0, 0);
    if (inside_cone(mu, stick(0), stick_t, scale)) {
      r = stick;
      return true;
    }
    if (!inside_cone(mu, r, scale)) r = project_on_coulomb_cone_of(mu, stick);
  }
  return newton_fallback(a, b, mu, r);
}

bool solve_single_contact(const LocalMatrix& a, const LocalVector& b, double mu, LocalVector& r) {
  const int d = static_cast<int>(b.size());
  if (d == 2) {  // in scalars: the sweeps' most common case
    const double nan = std::numeric_limits<double>::quiet_NaN();  // no start: the fallback's own
    double r_n = r.size() == 2 ? r(0) : nan, r_t = r.size() == 2 ? r(1) : nan;
    const bool exact = solve_single_contact_planar(a, b(0), b(1), mu, r_n, r_t);
    r.resize(2);
    r << r_n, r_t;
    return exact;
  }
  if (d == 3) {  // of fixed size: the spatial sweeps' case
    // No start: one outside the cone, so the Newton starts from the stick impulse projected.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Eigen::Vector3d r_fixed = r.size() == 3 ? Eigen::Vector3d(r) : Eigen::Vector3d::Constant(nan);
    const bool exact = solve_single_contact_spatial(a, b, mu, r_fixed);
    r = r_fixed;
    return exact;
  }
  return solve_single_contact_cases(a, b, mu, r);
}

}  // namespace impactbench::solvers
