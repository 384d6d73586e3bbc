#pragma once
// Closest-point geometry of the contact pairs of spatial rigid bodies, with the rates needed at
// acceleration level. Body a is the one the normal points to; body b may be static.
//
// Every pair is reduced to the same description: the gap h, the unit normal n (from b to a), and
// the witness points c_a = p_a + r_a on a and c_b = p_b + r_b on b (c_a − c_b = h n). The
// contact velocities are those of the material points at the witness points, so that for each
// direction d ∈ {n, t1, t2}
//     dᵀ u,   u = v_a + ω_a × r_a − v_b − ω_b × r_b,
// and, differentiating at fixed (v, ω) along q̇ = N(q) v,
//     d/dt (dᵀ u) = ḋᵀ u + dᵀ (ω_a × ṙ_a − ω_b × ṙ_b).
// The functions below therefore return (h, n, ṅ, r_a, ṙ_a, r_b, ṙ_b); ṙ is the rate of the
// geometric witness point relative to the body centre, not of a material point.
#include <Eigen/Core>

#include "lib/model/spatial/quaternion_kinematics.hpp"

namespace impactbench::model::spatial {

/// Pose and velocity of one body, all in the world frame.
template <typename Scalar>
struct BodyState {
  Vector3<Scalar> position = Vector3<Scalar>::Zero();
  Matrix3<Scalar> rotation = Matrix3<Scalar>::Identity();  ///< body → world
  Vector3<Scalar> linear_velocity = Vector3<Scalar>::Zero();
  Vector3<Scalar> angular_velocity = Vector3<Scalar>::Zero();
};

template <typename Scalar>
struct PairGeometry {
  Scalar gap{0};
  Vector3<Scalar> normal, normal_rate;
  Vector3<Scalar> arm_a, arm_a_rate;  ///< r_a = c_a − p_a and its rate
  Vector3<Scalar> arm_b, arm_b_rate;  ///< r_b = c_b − p_b and its rate (zero for static b)
};

/// Sphere a against the static plane {x : nᵀ(x − x0) = 0}: h = nᵀ(p − x0) − r.
template <typename Scalar>
PairGeometry<Scalar> sphere_plane(const BodyState<Scalar>& sphere, double radius,
                                  const Eigen::Vector3d& plane_point,
                                  const Eigen::Vector3d& plane_normal) {
  const Vector3<Scalar> n = plane_normal.cast<Scalar>();
  PairGeometry<Scalar> g;
  g.gap = n.dot(sphere.position - plane_point.cast<Scalar>()) - radius;
  g.normal = n;
  g.normal_rate.setZero();
  g.arm_a = -radius * n;
  g.arm_a_rate.setZero();
  g.arm_b.setZero();
  g.arm_b_rate.setZero();
  return g;
}

/// Offset of corner k (0..7) of a cuboid in body coordinates: bit i of k selects +e_i or −e_i.
template <typename Scalar>
Vector3<Scalar> cuboid_corner(const Eigen::Vector3d& half_extents, int k) {
  Eigen::Vector3d s;
  for (int i = 0; i < 3; ++i) s(i) = ((k >> i) & 1) ? half_extents(i) : -half_extents(i);
  return s.cast<Scalar>();
}

/// Corner k of cuboid a against a static plane: h = nᵀ(p + R s_k − x0); the arm is material,
/// so ṙ_a = ω × r_a.
template <typename Scalar>
PairGeometry<Scalar> cuboid_corner_plane(const BodyState<Scalar>& box,
                                         const Eigen::Vector3d& half_extents, int corner,
                                         const Eigen::Vector3d& plane_point,
                                         const Eigen::Vector3d& plane_normal) {
  const Vector3<Scalar> n = plane_normal.cast<Scalar>();
  PairGeometry<Scalar> g;
  g.arm_a = box.rotation * cuboid_corner<Scalar>(half_extents, corner);
  g.arm_a_rate = box.angular_velocity.cross(g.arm_a);
  g.gap = n.dot(box.position + g.arm_a - plane_point.cast<Scalar>());
  g.normal = n;
  g.normal_rate.setZero();
  g.arm_b.setZero();
  g.arm_b_rate.setZero();
  return g;
}

/// Spheres a and b: n = (p_a − p_b)/L, h = L − r_a − r_b, ṅ = (I − n nᵀ)(v_a − v_b)/L.
/// Coincident centres (L = 0) have no defined normal; +e_z is used there.
template <typename Scalar>
PairGeometry<Scalar> sphere_sphere(const BodyState<Scalar>& a, double radius_a,
                                   const BodyState<Scalar>& b, double radius_b) {
  using std::sqrt;
  const Vector3<Scalar> d = a.position - b.position;
  const Scalar length_sq = d.squaredNorm();
  PairGeometry<Scalar> g;
  if (value_of(length_sq) == 0.0) {
    g.gap = Scalar(-radius_a - radius_b);
    g.normal = Vector3<Scalar>::UnitZ();
    g.normal_rate.setZero();
  } else {
    const Scalar length = sqrt(length_sq);
    g.gap = length - radius_a - radius_b;
    g.normal = d / length;
    const Vector3<Scalar> dv = a.linear_velocity - b.linear_velocity;
    g.normal_rate = (dv - g.normal * g.normal.dot(dv)) / length;
  }
  g.arm_a = -radius_a * g.normal;
  g.arm_a_rate = -radius_a * g.normal_rate;
  g.arm_b = radius_b * g.normal;
  g.arm_b_rate = radius_b * g.normal_rate;
  return g;
}

/// Sphere a against cuboid b, in the box's frame: s = Rᵀ(p_a − p_b), ṡ = Rᵀ(v_a − v_b − ω_b ×
/// (p_a − p_b)).
///  - Centre outside: the closest box point c = clamp(s, −e, e); clamped coordinates stay on
///    their face (ċ_i = 0), the others follow s (ċ_i = ṡ_i). d = s − c, n_loc = d/‖d‖,
///    h = ‖d‖ − r.
///  - Centre inside: the nearest face i (largest |s_i| − e_i); n_loc = sign(s_i) e_i (constant),
///    h = |s_i| − e_i − r ≤ −r, c = s with c_i moved onto the face (ċ = ṡ, ċ_i = 0).
/// In the world: n = R n_loc, ṅ = ω_b × n + R ṅ_loc, r_b = R c, ṙ_b = ω_b × r_b + R ċ.
template <typename Scalar>
PairGeometry<Scalar> sphere_cuboid(const BodyState<Scalar>& sphere, double radius,
                                   const BodyState<Scalar>& box,
                                   const Eigen::Vector3d& half_extents) {
  using std::sqrt;
  const Matrix3<Scalar>& R = box.rotation;
  const Vector3<Scalar> offset = sphere.position - box.position;
  const Vector3<Scalar> s = R.transpose() * offset;
  const Vector3<Scalar> s_rate = R.transpose() * (sphere.linear_velocity - box.linear_velocity -
                                                  box.angular_velocity.cross(offset));

  Vector3<Scalar> c = s, c_rate = s_rate, n_loc, n_loc_rate = Vector3<Scalar>::Zero();
  Scalar gap;
  bool outside = false;
  for (int i = 0; i < 3; ++i) {
    const double si = value_of(s(i));
    if (si > half_extents(i) || si < -half_extents(i)) {
      outside = true;
      c(i) = Scalar(si > 0 ? half_extents(i) : -half_extents(i));
      c_rate(i) = Scalar(0);
    }
  }
  if (outside) {
    const Vector3<Scalar> d = s - c;
    const Vector3<Scalar> d_rate = s_rate - c_rate;
    const Scalar length = sqrt(d.squaredNorm());
    n_loc = d / length;
    n_loc_rate = (d_rate - n_loc * n_loc.dot(d_rate)) / length;
    gap = length - radius;
  } else {
    int face = 0;
    double best = -1e300;
    for (int i = 0; i < 3; ++i) {
      const double depth = std::abs(value_of(s(i))) - half_extents(i);  // ≤ 0 inside
      if (depth > best) {
        best = depth;
        face = i;
      }
    }
    const double sign = value_of(s(face)) >= 0.0 ? 1.0 : -1.0;
    n_loc = Vector3<Scalar>::Zero();
    n_loc(face) = Scalar(sign);
    gap = sign * s(face) - half_extents(face) - radius;
    c(face) = Scalar(sign * half_extents(face));
    c_rate(face) = Scalar(0);
  }

  PairGeometry<Scalar> g;
  g.gap = gap;
  g.normal = R * n_loc;
  g.normal_rate = box.angular_velocity.cross(g.normal) + R * n_loc_rate;
  g.arm_a = -radius * g.normal;
  g.arm_a_rate = -radius * g.normal_rate;
  g.arm_b = R * c;
  g.arm_b_rate = box.angular_velocity.cross(g.arm_b) + R * c_rate;
  return g;
}

}  // namespace impactbench::model::spatial
