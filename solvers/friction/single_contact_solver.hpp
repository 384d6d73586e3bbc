#pragma once
// Exact solution of the one-contact problem u = A r + b, K_μ ∋ r ⊥ u + g(u) ∈ K_μ*, the local
// step of nonsmooth Gauss–Seidel. Cases are tried in order and the first consistent one wins:
//   open   r = 0                          consistent if b_n ≥ 0;
//   stick  A r = −b                       consistent if r ∈ K_μ;
//   slip   u_n = 0, r_t = −μ r_n û_t      planar: closed form per sign of u_t (see .cpp);
//                                         spatial: Alart–Curnier Newton with line search.
#include <cmath>

#include "solvers/friction/coulomb_cone.hpp"

namespace impactbench::solvers {

/// Overwrites r (used as the starting point of the spatial slip Newton) with the solution.
/// Returns false when the local solve could not reach machine precision (r is then the best
/// iterate found). Requires A(0,0) > 0.
bool solve_single_contact(const LocalMatrix& a, const LocalVector& b, double mu, LocalVector& r);

/// The same for a spatial contact (A 3 × 3) in vectors of fixed size (solve_single_contact
/// calls it for d = 3), r in and out as above.
bool solve_single_contact_spatial(const Eigen::Matrix3d& a, const Eigen::Vector3d& b, double mu,
                                  Eigen::Vector3d& r);

/// The same for a planar contact (A 2 × 2), in scalars: the same cases, arithmetic and Newton
/// fallback (solve_single_contact calls it for d = 2); (r_n, r_t) in and out as r above.
bool solve_single_contact_planar(const LocalMatrix& a, double b_n, double b_t, double mu,
                                 double& r_n, double& r_t);

/// A spatial contact's local problem prepared once for a solve whose W_ii and μ do not change
/// (nsgs): W_ii itself (as a fixed-size matrix, which the sweep would otherwise convert from its
/// small dynamic one at every local solve) and its cofactors and determinant, with which the
/// stick case applies Cramer's rule. solve_single_contact_spatial prepares its contact and
/// solves it so: a sweep that prepares its contacts once gets the same cases, arithmetic and
/// impulses, to the bit.
struct PreparedSpatialContact {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();  ///< W_ii, which the Newton fallback reads
  double mu = 0.0;
  bool invertible = false;  ///< A passes the rank test of the stick case
  double det = 0.0;
  Eigen::Matrix3d cofactor = Eigen::Matrix3d::Zero();
};

/// Prepares `a` (3 × 3, A(0,0) > 0) with friction coefficient `mu`.
PreparedSpatialContact prepare_spatial_contact(const Eigen::Matrix3d& a, double mu);

/// solve_single_contact_spatial's cases with `prepared`; r in and out as there.
bool solve_prepared_spatial_contact(const PreparedSpatialContact& prepared,
                                    const Eigen::Vector3d& b, Eigen::Vector3d& r);

/// A planar contact's local problem prepared once for a solve whose W_ii and μ do not change
/// (nsgs): W_ii⁻¹ and each slip direction's pivot reciprocal, so that a sweep multiplies where
/// solve_single_contact_planar divides. The same cases in the same order; the impulses agree
/// with solve_single_contact_planar's to round-off, not to the bit. W_ii's own entries are kept
/// too (for the sweep's b_i and the Newton fallback), so that a sweep reads one record per
/// contact: the doubles first, then the flags, 120 bytes.
struct PreparedPlanarContact {
  double a[4] = {};  ///< W_ii, row-major
  double mu = 0.0;
  double inverse_a_nn = 0.0;           ///< 1 / A_nn, for the round-off slack's scale
  double inverse[4] = {};              ///< A⁻¹, row-major
  double inverse_pivot[2] = {};        ///< per slip direction σ = +1, −1
  double tangent_coefficient[2] = {};  ///< A_tn − σ μ A_tt
  bool invertible = false;             ///< A passes solve_single_contact_planar's rank test
  bool slips[2] = {};                  ///< the pivot A_nn − σ μ A_nt is positive
};
static_assert(sizeof(PreparedPlanarContact) == 120);

/// Prepares `a` (2 × 2, A(0,0) > 0) with friction coefficient `mu`.
PreparedPlanarContact prepare_planar_contact(const LocalMatrix& a, double mu);
/// The same for A given by its entries, row-major: the same record, to the bit.
PreparedPlanarContact prepare_planar_contact(const double (&a)[4], double mu);

/// The cases of solve_prepared_planar_contact after the open contact and the stick inside the
/// cone without slack: the stick within the round-off slack, the slips, the Newton fallback.
/// (stick_n, stick_t) is −A⁻¹ b when `prepared` is invertible.
bool solve_prepared_planar_contact_beyond_stick(const PreparedPlanarContact& prepared, double b_n,
                                                double b_t, double stick_n, double stick_t,
                                                double& r_n, double& r_t);

/// solve_single_contact_planar's cases with `prepared`. Inline up to the stick, the cases of
/// most contacts in a sweep.
inline bool solve_prepared_planar_contact(const PreparedPlanarContact& prepared, double b_n,
                                          double b_t, double& r_n, double& r_t) {
  if (b_n >= 0.0) {  // open
    r_n = 0.0;
    r_t = 0.0;
    return true;
  }
  double stick_n = 0.0, stick_t = 0.0;
  if (prepared.invertible) {  // stick: r = −A⁻¹ b, inside the cone without slack first
    stick_n = -(prepared.inverse[0] * b_n + prepared.inverse[1] * b_t);
    stick_t = -(prepared.inverse[2] * b_n + prepared.inverse[3] * b_t);
    if (stick_n >= 0.0 && std::abs(stick_t) <= prepared.mu * stick_n) {
      r_n = stick_n;
      r_t = stick_t;
      return true;
    }
  }
  return solve_prepared_planar_contact_beyond_stick(prepared, b_n, b_t, stick_n, stick_t, r_n, r_t);
}

}  // namespace impactbench::solvers
