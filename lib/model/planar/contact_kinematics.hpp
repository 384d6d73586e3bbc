#pragma once
// Gap, Jacobian rows and acceleration-level drift terms of one frozen ContactFeature, derived
// analytically for any scalar (double or Eigen::AutoDiffScalar).
//
// With material points p = c + r, r = R(θ) s:  ṗ = v + ω r⊥,  p̈|_{v̇=0} = −ω² r,  where
// a⊥ = (−a_y, a_x) = ∂(R a)/∂θ for a = R s. Let d = p_a − p_b.
//   fixed n:      ṅ = 0,              n̈ = 0
//   n of b:       ṅ = ω_b n⊥,         n̈ = −ω_b² n
//   along d:      n = d/‖d‖, ṅ = (ḋ − n nᵀḋ)/‖d‖
// Normal (h the gap):  ḣ = ṅᵀd + nᵀḋ = w_nᵀv,   ẇ_nᵀv = ḧ|_{v̇=0} = n̈ᵀd + 2ṅᵀḋ + nᵀd̈
// (along d: ḣ = nᵀḋ, ḧ = nᵀd̈ + ṅᵀḋ).
// Tangent t = n⊥, contact point x_c = p_a − radius_a n; the tangential relative velocity is that
// of the material points of a and b at x_c:
//   ζ_t(q, v) = tᵀ[v_a + ω_a (x_c − c_a)⊥ − v_b − ω_b (x_c − c_b)⊥] = W_tᵀ v,
//   Ẇ_tᵀv = (∂ζ_t/∂q) q̇ = ṫᵀu + tᵀ[ω_a (ẋ_c − v_a)⊥ − ω_b (ẋ_c − v_b)⊥],  u the bracket above.
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "lib/model/autodiff.hpp"
#include "lib/model/contact.hpp"
#include "lib/model/contact_storage.hpp"
#include "lib/model/planar/contact_feature.hpp"

namespace impactbench::model::planar {

template <typename Scalar>
using Vec2 = Eigen::Matrix<Scalar, 2, 1>;

template <typename Scalar>
Vec2<Scalar> perp(const Vec2<Scalar>& a) {
  return Vec2<Scalar>(-a.y(), a.x());
}

template <typename Scalar>
Eigen::Matrix<Scalar, 2, 2> rotation(const Scalar& theta) {
  using std::cos;
  using std::sin;
  const Scalar c = cos(theta);
  const Scalar s = sin(theta);
  Eigen::Matrix<Scalar, 2, 2> r;
  r << c, -s, s, c;
  return r;
}

/// Position and velocity of one body's centre and rotation, slices of q and v.
template <typename Scalar>
struct BodyMotion {
  Vec2<Scalar> centre = Vec2<Scalar>::Zero();
  /// rotation(θ) of the body's angle θ, formed once per body by the caller (a body is in
  /// several contacts).
  Eigen::Matrix<Scalar, 2, 2> rotation = Eigen::Matrix<Scalar, 2, 2>::Identity();
  Vec2<Scalar> velocity = Vec2<Scalar>::Zero();
  Scalar omega{0};
  int first_velocity = 0;
};

/// Each body's rotation(θ), formed when a contact first needs it during one contact search (a
/// body is in several contacts); reset per search.
template <typename Scalar>
struct BodyRotations {
  std::vector<Eigen::Matrix<Scalar, 2, 2>> rotations;
  std::vector<char> formed;
  void reset(std::size_t bodies) {
    rotations.resize(bodies);
    formed.assign(bodies, 0);
  }
};

/// The material points of a feature on a and b, r = R s from each body's centre c, and their
/// separation d = p_a − p_b. b == nullptr means the static environment (feature.s_b is then a
/// world point).
template <typename Scalar>
struct FeaturePoints {
  Vec2<Scalar> r_a, p_a, r_b, c_b, p_b, d;
};

// Inlined into evaluate_contact, where a call and the struct's copy cost a sixth of it.
template <typename Scalar>
[[gnu::always_inline]] inline FeaturePoints<Scalar> feature_points(const ContactFeature& feature,
                                                                   const BodyMotion<Scalar>& a,
                                                                   const BodyMotion<Scalar>* b) {
  using V2 = Vec2<Scalar>;
  FeaturePoints<Scalar> p;
  p.r_a = a.rotation * feature.s_a.template cast<Scalar>();
  p.p_a = a.centre + p.r_a;
  p.r_b = b ? V2(b->rotation * feature.s_b.template cast<Scalar>()) : V2(V2::Zero());
  p.c_b = b ? b->centre : V2(feature.s_b.template cast<Scalar>());
  p.p_b = p.c_b + p.r_b;
  p.d = p.p_a - p.p_b;
  return p;
}

/// The normal n of a feature at its points and the gap h along it; `length` is ‖d‖ for a
/// normal along d.
template <typename Scalar>
struct FeatureNormal {
  Vec2<Scalar> n;
  Scalar gap;
  Scalar length;  // set for a normal along d only
};

/// The one computation of a feature's gap: evaluate_contact and the gaps alone
/// (PlanarRigidBodySystem::find_contact_gaps) both take it from here, so they agree to the bit.
template <typename Scalar>
[[gnu::always_inline]] inline FeatureNormal<Scalar> feature_normal(const ContactFeature& feature,
                                                                   const FeaturePoints<Scalar>& p,
                                                                   const BodyMotion<Scalar>* b) {
  using V2 = Vec2<Scalar>;
  using std::sqrt;
  FeatureNormal<Scalar> out;
  switch (feature.kind) {
    case NormalKind::kFixedNormal:
      out.n = feature.n_b.template cast<Scalar>();
      out.gap = out.n.dot(p.d) - Scalar(feature.offset);
      break;
    case NormalKind::kNormalOfB:
      out.n = b ? V2(b->rotation * feature.n_b.template cast<Scalar>())
                : V2(feature.n_b.template cast<Scalar>());
      out.gap = out.n.dot(p.d) - Scalar(feature.offset);
      break;
    case NormalKind::kAlongSeparation:
      out.length = sqrt(p.d.squaredNorm());
      out.n = p.d / out.length;
      out.gap = out.length - Scalar(feature.offset);
      break;
  }
  return out;
}

/// Fills every field of `c` but name, friction and restitution, reusing its storage.
/// b == nullptr means the static environment (feature.s_b is then a world point).
template <typename Scalar>
void evaluate_contact(const ContactFeature& feature, const BodyMotion<Scalar>& a,
                      const BodyMotion<Scalar>* b, Contact<Scalar>& c) {
  using V2 = Vec2<Scalar>;
  const Scalar zero(0);

  const FeaturePoints<Scalar> points = feature_points(feature, a, b);
  const V2 &r_a = points.r_a, &p_a = points.p_a, &r_b = points.r_b, &c_b = points.c_b,
           &d = points.d;
  const V2 pdot_a = a.velocity + a.omega * perp(r_a);
  const V2 pddot_a = -(a.omega * a.omega) * r_a;

  const Scalar omega_b = b ? b->omega : zero;
  const V2 v_b = b ? b->velocity : V2(V2::Zero());
  const V2 pdot_b = v_b + omega_b * perp(r_b);
  const V2 pddot_b = -(omega_b * omega_b) * r_b;

  const V2 ddot = pdot_a - pdot_b;
  const V2 dddot = pddot_a - pddot_b;

  const FeatureNormal<Scalar> normal = feature_normal(feature, points, b);
  const V2& n = normal.n;
  const Scalar& gap = normal.gap;
  V2 ndot = V2::Zero();
  Scalar normal_drift = zero;
  // Coefficient of ω_b in ḣ beyond the material-point term (n turning with b).
  Scalar omega_b_normal_extra = zero;
  switch (feature.kind) {
    case NormalKind::kFixedNormal:
      normal_drift = n.dot(dddot);
      break;
    case NormalKind::kNormalOfB: {
      ndot = omega_b * perp(n);
      const V2 nddot = -(omega_b * omega_b) * n;
      normal_drift = nddot.dot(d) + Scalar(2) * ndot.dot(ddot) + n.dot(dddot);
      omega_b_normal_extra = perp(n).dot(d);
      break;
    }
    case NormalKind::kAlongSeparation:
      ndot = (ddot - n * n.dot(ddot)) / normal.length;
      normal_drift = n.dot(dddot) + ndot.dot(ddot);
      break;
  }

  const V2 t = perp(n);
  const V2 tdot = perp(ndot);
  const V2 x_c = p_a - Scalar(feature.radius_a) * n;
  const V2 xdot_c = pdot_a - Scalar(feature.radius_a) * ndot;
  const V2 lever_a = x_c - a.centre;
  const V2 lever_b = x_c - c_b;
  const V2 u = a.velocity + a.omega * perp(lever_a) - v_b - omega_b * perp(lever_b);

  c.key = feature.key;
  c.gap = gap;
  c.normal_drift = normal_drift;
  c.tangent_drift.resize(1);
  c.tangent_drift(0) = tdot.dot(u) + t.dot(a.omega * perp(V2(xdot_c - a.velocity)) -
                                           omega_b * perp(V2(xdot_c - v_b)));

  c.blocks.reserve(2);  // room for two bodies at once: a slot's one-body contact may become two
  resize_blocks(c.blocks, b ? 2 : 1);
  JacobianBlock<Scalar>& block_a = c.blocks[0];
  block_a.first_velocity = a.first_velocity;
  block_a.rows.resize(2, 3);
  block_a.rows << n.x(), n.y(), n.dot(perp(r_a)), t.x(), t.y(), t.dot(perp(lever_a));
  if (b) {
    JacobianBlock<Scalar>& block_b = c.blocks[1];
    block_b.first_velocity = b->first_velocity;
    block_b.rows.resize(2, 3);
    block_b.rows << -n.x(), -n.y(), omega_b_normal_extra - n.dot(perp(r_b)), -t.x(), -t.y(),
        -t.dot(perp(lever_b));
  }

  c.point = Eigen::Vector3d(value_of(x_c.x()), value_of(x_c.y()), 0.0);
  c.normal = Eigen::Vector3d(value_of(n.x()), value_of(n.y()), 0.0);
}

}  // namespace impactbench::model::planar
