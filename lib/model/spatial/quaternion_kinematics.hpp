#pragma once
// Unit-quaternion kinematics for bodies whose angular velocity ω is expressed in the WORLD frame.
// A quaternion is stored (w, x, y, z) and rotates body coordinates into world coordinates.
//
//   q̇uat = ½ (0, ω) ⊗ quat                   (world-frame ω multiplies from the left)
//   quat(t + h) = exp(½ h (0, ω)) ⊗ quat(t)   (exact flow of the above for constant ω)
//
// The exponential of the pure quaternion (0, φ/2), φ = h ω, is (cos ‖φ‖/2, sinc(‖φ‖/2) φ/2); near
// φ = 0 the series is used so that no square root of zero is taken (autodiff-safe).
#include <cmath>

#include <Eigen/Core>

#include "lib/model/spatial/scalar_value.hpp"

namespace impactbench::model::spatial {

template <typename Scalar>
using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
template <typename Scalar>
using Vector4 = Eigen::Matrix<Scalar, 4, 1>;
template <typename Scalar>
using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;

/// Hamilton product a ⊗ b of quaternions stored (w, x, y, z).
template <typename Scalar>
Vector4<Scalar> quaternion_product(const Vector4<Scalar>& a, const Vector4<Scalar>& b) {
  const Vector3<Scalar> av = a.template tail<3>();
  const Vector3<Scalar> bv = b.template tail<3>();
  Vector4<Scalar> r;
  r(0) = a(0) * b(0) - av.dot(bv);
  r.template tail<3>() = a(0) * bv + b(0) * av + av.cross(bv);
  return r;
}

/// Rotation matrix (body → world) of a unit quaternion (w, x, y, z).
template <typename Scalar>
Matrix3<Scalar> rotation_matrix(const Vector4<Scalar>& q) {
  const Scalar w = q(0), x = q(1), y = q(2), z = q(3);
  Matrix3<Scalar> R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

/// q̇uat = ½ (0, ω) ⊗ quat for world-frame ω.
template <typename Scalar>
Vector4<Scalar> quaternion_rate(const Vector4<Scalar>& quat, const Vector3<Scalar>& omega) {
  Vector4<Scalar> pure;
  pure << Scalar(0), omega;
  return Scalar(0.5) * quaternion_product(pure, quat);
}

/// exp(½ (0, φ)): the unit quaternion of the rotation by the rotation vector φ.
template <typename Scalar>
Vector4<Scalar> rotation_exponential(const Vector3<Scalar>& phi) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const Scalar s = Scalar(0.25) * phi.squaredNorm();  // (‖φ‖/2)²
  Scalar cosine, sinc;
  if (value_of(s) < 1e-8) {
    // Truncation error below θ⁶/720 ≈ 1e-27: exact in double.
    cosine = Scalar(1) - s / 2 + s * s / 24;
    sinc = Scalar(1) - s / 6 + s * s / 120;
  } else {
    const Scalar theta = sqrt(s);
    cosine = cos(theta);
    sinc = sin(theta) / theta;
  }
  Vector4<Scalar> r;
  r << cosine, Scalar(0.5) * sinc * phi;
  return r;
}

/// quat advanced by h at constant world-frame ω, renormalised against rounding drift.
template <typename Scalar>
Vector4<Scalar> integrate_quaternion(const Vector4<Scalar>& quat, const Vector3<Scalar>& omega,
                                     const Scalar& h) {
  const Vector3<Scalar> phi = h * omega;
  const Vector4<Scalar> r = quaternion_product(rotation_exponential(phi), quat);
  return r / r.norm();
}

}  // namespace impactbench::model::spatial
