#pragma once
// Projections used by every friction solver: the Coulomb cone K_μ = {x : ‖x_t‖ ≤ μ x_n}
// (normal first) and the friction disk {x_t : ‖x_t‖ ≤ radius} of B.16/B.17.
#include <Eigen/Core>

#include "solvers/common/select_bits.hpp"

namespace impactbench::solvers {

/// Per-contact vectors and matrices: at most 3 components, never heap-allocated.
using LocalVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 3, 1>;
using LocalMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 3, 3>;

/// Euclidean projection of x = (x_n, x_t) onto K_μ, μ ≥ 0. With s = ‖x_t‖:
///  (1) x ∈ K_μ (s ≤ μ x_n, x_n ≥ 0): x itself;
///  (2) x in the polar cone (μ s ≤ −x_n): the apex 0;
///  (3) otherwise the nearest point of the boundary ray {(t, μ t x_t/s) : t ≥ 0}, found by
///      minimising (x_n − t)² + (s − μ t)²: t = (x_n + μ s) / (1 + μ²).
LocalVector project_on_coulomb_cone(double mu, const LocalVector& x);

/// That projection in terms of x_n and s = ‖x_t‖ (the three cases above, in one place for the
/// vector form and for scalar callers): its normal part, and the factor that turns x_t into its
/// tangential part (1 in case (1), μ t / s in case (3)); at the apex both parts are zero.
struct ConeProjection {
  double normal;
  double tangent_factor;
  bool apex;
};
inline ConeProjection coulomb_cone_projection(double mu, double normal, double slip) {
  const bool inside = (normal >= 0.0) & (slip <= mu * normal);
  const bool apex = !inside & (mu * slip <= -normal);
  // Case (3)'s values are formed whatever the case and picked without a branch (select_bits):
  // the case of a contact is not predictable, and a mispredicted branch cost more than the two
  // divisions. (s > 0 in case (3), since s = 0 falls in case (1) or (2).)
  const double t = (normal + mu * slip) / (1.0 + mu * mu);
  const double factor = mu * t / slip;
  return {select_bits(inside, normal, select_bits(apex, 0.0, t)),
          select_bits(inside, 1.0, select_bits(apex, 0.0, factor)), apex};
}

/// The tangential components of a contact's vector of type `Vector` (all but the normal one),
/// counted at compile time: Eigen::Dynamic for LocalVector, the size less one for a fixed size.
template <typename Vector>
inline constexpr int kTangentSize =
    Vector::RowsAtCompileTime == Eigen::Dynamic ? Eigen::Dynamic : Vector::RowsAtCompileTime - 1;

/// project_on_coulomb_cone for `Vector` LocalVector, or of fixed size.
template <typename Vector>
Vector project_on_coulomb_cone_of(double mu, const Vector& x) {
  constexpr int kTangent = kTangentSize<Vector>;
  const auto tangent = x.template segment<kTangent>(1, x.size() - 1);
  const ConeProjection p = coulomb_cone_projection(mu, x(0), tangent.norm());
  if (p.apex) return Vector::Zero(x.size());
  Vector projected(x.size());
  projected(0) = p.normal;
  projected.template segment<kTangent>(1, x.size() - 1) = p.tangent_factor * tangent;
  return projected;
}

/// Projection of a tangential vector onto the disk of the given radius (≥ 0) (B.16).
LocalVector project_on_disk(double radius, const LocalVector& x_t);

/// The same for a tangential vector of type `Vector`: LocalVector, or one of fixed size.
template <typename Vector>
Vector project_on_disk_of(double radius, const Vector& x_t) {
  const double length = x_t.norm();
  if (length <= radius) return x_t;
  if (radius <= 0.0 || length == 0.0) return Vector::Zero(x_t.size());
  return (radius / length) * x_t;
}

}  // namespace impactbench::solvers
