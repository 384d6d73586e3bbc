#pragma once
// The tangent directions t1, t2 of a contact with unit normal n, and their rates for a given ṅ.
//
// Construction (after Frisvad 2012, "Building an orthonormal basis from a 3D unit vector without
// normalization"), with σ = +1 on the upper cap n_z ≥ −½ and σ = −1 on the lower cap n_z < −½:
//     a = 1 / (1 + σ n_z),   b = −n_x n_y a,
//     t1 = (1 − n_x² a, b, −σ n_x),   t2 = σ (b, 1 − n_y² a, −σ n_y).
// (n, t1, t2) is orthonormal and right-handed (t1 × t2 = n). Each cap's formula is smooth (C∞)
// over the whole cap (its only singularity, n = −σ e_z, lies in the other cap), so the frame is
// discontinuous only across the circle n_z = −½. A floor (n = +e_z) gets t1 = e_x, t2 = e_y, and
// walls (n_z = 0) lie well inside the upper cap.
#include "lib/model/spatial/quaternion_kinematics.hpp"

namespace impactbench::model::spatial {

template <typename Scalar>
struct TangentFrame {
  Vector3<Scalar> t1, t2;            ///< unit tangents, t1 × t2 = n
  Vector3<Scalar> t1_rate, t2_rate;  ///< ṫ1, ṫ2 for the given ṅ
};

/// n must be unit; n_rate must be orthogonal to n (the rate of a unit vector).
template <typename Scalar>
TangentFrame<Scalar> tangent_frame(const Vector3<Scalar>& n, const Vector3<Scalar>& n_rate) {
  const double sigma = value_of(n.z()) >= -0.5 ? 1.0 : -1.0;
  const Scalar a = Scalar(1) / (Scalar(1) + sigma * n.z());
  const Scalar a_rate = -sigma * a * a * n_rate.z();
  const Scalar b = -n.x() * n.y() * a;
  const Scalar b_rate = -(n_rate.x() * n.y() * a + n.x() * n_rate.y() * a + n.x() * n.y() * a_rate);
  TangentFrame<Scalar> f;
  f.t1 << Scalar(1) - n.x() * n.x() * a, b, -sigma * n.x();
  f.t2 << sigma * b, sigma * (Scalar(1) - n.y() * n.y() * a), -n.y();
  f.t1_rate << -2 * n.x() * n_rate.x() * a - n.x() * n.x() * a_rate, b_rate, -sigma * n_rate.x();
  f.t2_rate << sigma * b_rate, sigma * (-2 * n.y() * n_rate.y() * a - n.y() * n.y() * a_rate),
      -n_rate.y();
  return f;
}

}  // namespace impactbench::model::spatial
