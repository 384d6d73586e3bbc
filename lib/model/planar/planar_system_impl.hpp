#pragma once
// Definitions of PlanarRigidBodySystem<Scalar>; included only by the explicit instantiations
// (planar_system.cpp for double, planar_system_autodiff.cpp for AutoDiffScalar).
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "lib/model/autodiff.hpp"
#include "lib/model/body_reach.hpp"
#include "lib/model/broad_phase/overlapping_pair_cache.hpp"
#include "lib/model/broad_phase/uniform_grid.hpp"
#include "lib/model/contact_name.hpp"
#include "lib/model/contact_prefetch.hpp"
#include "lib/model/contact_storage.hpp"
#include "lib/model/planar/contact_kinematics.hpp"
#include "lib/model/planar/narrow_phase.hpp"
#include "lib/model/planar/planar_system.hpp"
#include "lib/output/column_names.hpp"
#include "lib/output/number_text.hpp"  // doubles in messages as they were given

namespace impactbench::model::planar {
namespace detail {

[[noreturn]] inline void fail(const std::string& what) {
  throw std::invalid_argument("PlanarRigidBodySystem: " + what);
}

inline void require(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

inline std::string body_label(const BodySpec& b) {
  return "body '" + b.name + "'";
}

inline bool positive_finite(double x) {
  return std::isfinite(x) && x > 0.0;
}

}  // namespace detail

template <typename Scalar>
PlanarRigidBodySystem<Scalar>::PlanarRigidBodySystem(std::vector<BodySpec> bodies,
                                                     std::vector<StaticPlaneSpec> planes,
                                                     double gravity, Material material,
                                                     std::vector<ForceInputSpec> inputs)
    : gravity_(gravity), material_(material) {
  using detail::require;
  require(std::isfinite(gravity), "gravity must be finite, got " + output::number_text(gravity));
  require(
      std::isfinite(material.friction) && material.friction >= 0.0,
      "material friction must be finite and >= 0, got " + output::number_text(material.friction));
  require(
      material.restitution >= 0.0 && material.restitution <= 1.0,
      "material restitution must be in [0, 1], got " + output::number_text(material.restitution));

  std::unordered_map<std::string, int> index_of;
  for (BodySpec& spec : bodies) {
    const std::string label = detail::body_label(spec);
    require(!spec.name.empty(), "a body has an empty name");
    require(index_of.emplace(spec.name, num_bodies()).second, label + ": duplicate name");
    require(detail::positive_finite(spec.mass),
            label + ": mass must be finite and > 0, got " + output::number_text(spec.mass));
    require(spec.position.allFinite() && std::isfinite(spec.angle) && spec.velocity.allFinite() &&
                spec.angular_velocity.allFinite(),
            label + ": initial position, angle and velocities must be finite");
    Body body;
    BodyProperties properties;
    properties.mass = spec.mass;
    properties.radius = spec.radius;
    if (spec.shape == ShapeKind::kDisk) {
      require(detail::positive_finite(spec.radius),
              label + ": radius must be finite and > 0, got " + output::number_text(spec.radius));
      properties.inertia = 0.5 * spec.mass * spec.radius * spec.radius;
      properties.bounding_radius = spec.radius;
    } else if (spec.shape == ShapeKind::kBox) {
      require(detail::positive_finite(spec.size.x()) && detail::positive_finite(spec.size.y()),
              label + ": size (width, height) must be finite and > 0, got (" +
                  output::number_text(spec.size.x()) + ", " + output::number_text(spec.size.y()) +
                  ")");
      properties.inertia = spec.mass * spec.size.head<2>().squaredNorm() / 12.0;
      body.polygon = make_box_polygon(spec.size.x(), spec.size.y());
      properties.bounding_radius = body.polygon.bounding_radius();
      properties.disk = false;
    } else {
      detail::fail(label + ": shape must be a disk or a box in a planar system");
    }
    names_.push_back(spec.name);
    body.spec = std::move(spec);
    bodies_.push_back(std::move(body));
    properties_.push_back(properties);
  }

  for (const StaticPlaneSpec& plane : planes) {
    const std::string label = "plane '" + plane.name + "'";
    const Eigen::Vector2d normal = plane.normal.head<2>();
    require(plane.point.allFinite(), label + ": point must be finite");
    require(normal.allFinite() && normal.norm() > 1e-12,
            label + ": normal must be finite and non-zero in the x-y plane");
    lines_.push_back({plane.name, plane.point.head<2>(), normal.normalized()});
  }

  for (const ForceInputSpec& input : inputs) {
    const auto it = index_of.find(input.body);
    require(it != index_of.end(), "input on unknown body '" + input.body + "'");
    const Eigen::Vector2d direction = input.direction.head<2>();
    require(direction.allFinite() && direction.norm() > 1e-12,
            "input on body '" + input.body + "': direction must be finite and non-zero in x-y");
    inputs_.push_back({it->second, direction});
  }

  // The names of the body–line contacts, written into every contact found: copied from here
  // instead of composed again at each contact search.
  for (int i = 0; i < num_bodies(); ++i) {
    line_name_offset_.push_back(line_contact_names_.size());
    const int per_line = line_features_of(i);
    for (int k = 0; k < static_cast<int>(lines_.size()); ++k)
      for (int local = 0; local < per_line; ++local)
        compose_contact_name({i, -1, k * kFeaturesPerPlane + local},
                             line_contact_names_.emplace_back());
  }
  // The longest name a contact can get: a body–line name above, or "<a>-<b>" with "#<feature>"
  // when a polygon is involved.
  std::size_t longest_body_name = 0;
  bool polygons = false;
  for (int i = 0; i < num_bodies(); ++i) {
    longest_body_name = std::max(longest_body_name, body(i).name.size());
    polygons = polygons || !properties_[static_cast<std::size_t>(i)].disk;
  }
  contact_name_capacity_ =
      2 * longest_body_name + 1 +
      (polygons ? 1 + std::to_string(std::numeric_limits<int>::min()).size() : 0);
  for (const std::string& name : line_contact_names_)
    contact_name_capacity_ = std::max(contact_name_capacity_, name.size());
}

template <typename Scalar>
int PlanarRigidBodySystem<Scalar>::line_features_of(int body) const {
  const auto i = static_cast<std::size_t>(body);
  return properties_[i].disk ? 1 : static_cast<int>(bodies_[i].polygon.vertices.size());
}

template <typename Scalar>
void PlanarRigidBodySystem<Scalar>::fail_sizes(const Vector& q, const Vector* v) const {
  if (q.size() != num_positions())
    detail::fail("q has size " + std::to_string(q.size()) + ", expected " +
                 std::to_string(num_positions()));
  detail::fail("v has size " + std::to_string(v->size()) + ", expected " +
               std::to_string(num_velocities()));
}

template <typename Scalar>
auto PlanarRigidBodySystem<Scalar>::mass_matrix(const Vector& q) const -> SparseMatrix {
  check_sizes(q, nullptr);
  SparseMatrix m(num_velocities(), num_velocities());
  m.reserve(Eigen::VectorXi::Constant(num_velocities(), 1));
  for (int i = 0; i < num_bodies(); ++i) {
    m.insert(3 * i, 3 * i) = Scalar(mass(i));
    m.insert(3 * i + 1, 3 * i + 1) = Scalar(mass(i));
    m.insert(3 * i + 2, 3 * i + 2) = Scalar(inertia(i));
  }
  m.makeCompressed();
  return m;
}

template <typename Scalar>
auto PlanarRigidBodySystem<Scalar>::bias_forces(const Vector& q, const Vector& v) const -> Vector {
  Vector h;
  write_bias_forces(q, v, h);
  return h;
}

template <typename Scalar>
void PlanarRigidBodySystem<Scalar>::write_bias_forces(const Vector& q, const Vector& v,
                                                      Vector& out) const {
  check_sizes(q, &v);
  // B.2 keeps H on the left: gravity −m g ŷ enters as H_y = +m g.
  out.setZero(num_velocities());
  for (int i = 0; i < num_bodies(); ++i) out(3 * i + 1) = Scalar(mass(i) * gravity_);
}

template <typename Scalar>
auto PlanarRigidBodySystem<Scalar>::input_matrix(const Vector& q) const -> Matrix {
  check_sizes(q, nullptr);
  Matrix s = Matrix::Zero(num_velocities(), num_inputs());
  for (int k = 0; k < num_inputs(); ++k) {
    const Input& input = inputs_[static_cast<std::size_t>(k)];
    s(3 * input.body, k) = Scalar(input.direction.x());
    s(3 * input.body + 1, k) = Scalar(input.direction.y());
  }
  return s;
}

template <typename Scalar>
auto PlanarRigidBodySystem<Scalar>::position_rate(const Vector& q, const Vector& v) const
    -> Vector {
  check_sizes(q, &v);
  return v;
}

template <typename Scalar>
void PlanarRigidBodySystem<Scalar>::write_position_rate(const Vector& q, const Vector& v,
                                                        Eigen::Ref<Vector> out) const {
  check_sizes(q, &v);
  out = v;
}

template <typename Scalar>
auto PlanarRigidBodySystem<Scalar>::integrate_position(const Vector& q, const Vector& v,
                                                       const Scalar& h) const -> Vector {
  Vector next;
  write_integrated_position(q, v, h, next);
  return next;
}

template <typename Scalar>
void PlanarRigidBodySystem<Scalar>::write_integrated_position(const Vector& q, const Vector& v,
                                                              const Scalar& h, Vector& out) const {
  check_sizes(q, &v);
  out = q + h * v;
}

template <typename Scalar>
Scalar PlanarRigidBodySystem<Scalar>::energy(const Vector& q, const Vector& v) const {
  check_sizes(q, &v);
  Scalar e(0);
  for (int i = 0; i < num_bodies(); ++i) {
    const auto vi = v.template segment<3>(3 * i);
    e += Scalar(0.5 * mass(i)) * (vi(0) * vi(0) + vi(1) * vi(1)) +
         Scalar(0.5 * inertia(i)) * vi(2) * vi(2) + Scalar(mass(i) * gravity_) * q(3 * i + 1);
  }
  return e;
}

template <typename Scalar>
std::vector<std::string> PlanarRigidBodySystem<Scalar>::position_names() const {
  return output::rigid_body_position_names(body_names(), false);
}

template <typename Scalar>
std::vector<std::string> PlanarRigidBodySystem<Scalar>::velocity_names() const {
  return output::rigid_body_velocity_names(body_names(), false);
}

template <typename Scalar>
Eigen::VectorXd PlanarRigidBodySystem<Scalar>::initial_positions() const {
  Eigen::VectorXd q(num_positions());
  for (int i = 0; i < num_bodies(); ++i)
    q.segment<3>(3 * i) << body(i).position.x(), body(i).position.y(), body(i).angle;
  return q;
}

template <typename Scalar>
Eigen::VectorXd PlanarRigidBodySystem<Scalar>::initial_velocities() const {
  Eigen::VectorXd v(num_velocities());
  for (int i = 0; i < num_bodies(); ++i)
    v.segment<3>(3 * i) << body(i).velocity.x(), body(i).velocity.y(), body(i).angular_velocity.z();
  return v;
}

template <typename Scalar>
void PlanarRigidBodySystem<Scalar>::find_contacts(const Vector& q, const Vector& v, double margin,
                                                  std::vector<Contact<Scalar>>& out) const {
  check_sizes(q, &v);
  thread_local std::vector<ContactFeature> features;  // storage kept between calls
  detect_features(q, margin, {}, features);
  evaluate_features(features, q, v, out);
}

template <typename Scalar>
bool PlanarRigidBodySystem<Scalar>::find_reachable_contacts(
    const Vector& q, const Vector& v, const Eigen::VectorXd& speed_bound, double horizon,
    double margin, std::vector<Contact<Scalar>>& out) const {
  check_sizes(q, &v);
  thread_local std::vector<double> reach;  // storage kept between calls
  body_reaches(
      speed_bound, horizon, num_bodies(), 2, 1,
      [&](int i) { return properties_[static_cast<std::size_t>(i)].bounding_radius; },
      [&](int i) { return body(i).name; }, "PlanarRigidBodySystem: ", reach);
  thread_local std::vector<ContactFeature> features;
  detect_features(q, margin, reach, features);
  evaluate_features(features, q, v, out, ContactNaming::kUnnamed);
  return true;
}

template <typename Scalar>
std::vector<ContactFeature> PlanarRigidBodySystem<Scalar>::detect_features(
    const Vector& q, double margin, std::span<const double> reach) const {
  std::vector<ContactFeature> features;
  detect_features(q, margin, reach, features);
  return features;
}

template <typename Scalar>
void PlanarRigidBodySystem<Scalar>::detect_features(const Vector& q, double margin,
                                                    std::span<const double> reach,
                                                    std::vector<ContactFeature>& features) const {
  check_sizes(q, nullptr);
  if (!(std::isfinite(margin) && margin >= 0.0))
    detail::fail("contact margin must be finite and >= 0, got " + output::number_text(margin));
  if (!reach.empty() && reach.size() != bodies_.size())
    detail::fail("reach has " + std::to_string(reach.size()) + " entries for " +
                 std::to_string(bodies_.size()) + " bodies");
  const auto reach_of = [&](int i) {
    return reach.empty() ? 0.0 : reach[static_cast<std::size_t>(i)];
  };

  // Geometry decisions on double values only (autodiff-safe). The scratch is kept per thread:
  // the event-driven integrator looks for contacts at every right-hand side and guard value.
  thread_local std::vector<ShapeRef> shapes;
  thread_local std::vector<Aabb> boxes;
  shapes.assign(bodies_.size(), ShapeRef{});
  boxes.resize(bodies_.size());
  for (int i = 0; i < num_bodies(); ++i) {
    const BodyProperties& b = properties_[static_cast<std::size_t>(i)];
    ShapeRef& s = shapes[static_cast<std::size_t>(i)];
    s.index = i;
    s.pose.centre = {value_of(q(3 * i)), value_of(q(3 * i + 1))};
    s.pose.angle = value_of(q(3 * i + 2));
    if (!(s.pose.centre.allFinite() && std::isfinite(s.pose.angle)))
      detail::fail("q of " + detail::body_label(body(i)) + " is not finite");
    s.radius = b.radius;
    s.polygon = b.disk ? nullptr : &bodies_[static_cast<std::size_t>(i)].polygon;
    const Eigen::Vector3d extent =
        Eigen::Vector3d(1.0, 1.0, 0.0) * (b.bounding_radius + margin + reach_of(i));
    const Eigen::Vector3d centre(s.pose.centre.x(), s.pose.centre.y(), 0.0);
    boxes[static_cast<std::size_t>(i)] = {centre - extent, centre + extent};
  }

  features.clear();
  for (int k = 0; k < static_cast<int>(lines_.size()); ++k) {
    const Line& l = lines_[static_cast<std::size_t>(k)];
    const planar::Line line{k, l.point, l.normal};
    for (const ShapeRef& s : shapes)
      collide_with_line(s, line, margin + reach_of(s.index), features);
  }
  // The grid's pairs kept across calls while the bodies stay within the cache's skin.
  thread_local OverlappingPairCache pair_cache;
  thread_local OverlappingPairs pairs;
  if (broad_phase_ == BroadPhase::kUniformGrid)
    pair_cache.find(boxes, pairs);
  else
    find_overlapping_pairs_brute_force(boxes, pairs);
  for (const auto& [i, j] : pairs)
    collide_shapes(shapes[static_cast<std::size_t>(i)], shapes[static_cast<std::size_t>(j)],
                   margin + reach_of(i) + reach_of(j), features);
}

template <typename Scalar>
void PlanarRigidBodySystem<Scalar>::evaluate_features(const std::vector<ContactFeature>& features,
                                                      const Vector& q, const Vector& v,
                                                      std::vector<Contact<Scalar>>& out,
                                                      ContactNaming naming) const {
  check_sizes(q, &v);
  resize_contacts(out, features.size());  // contacts are overwritten in place, keeping storage
  // Each body's rotation, formed when a contact first needs it (thread-local scratch, as in
  // detect_features).
  thread_local BodyRotations<Scalar> rotations;
  rotations.reset(bodies_.size());
  for (std::size_t k = 0; k < features.size(); ++k) {
    prefetch_contact_storage<Scalar>(out, k);
    const ContactFeature& f = features[k];
    Contact<Scalar>& c = out[k];
    const BodyMotion<Scalar> a = body_motion(f.key.body_a, q, v, rotations);
    if (f.key.body_b < 0) {
      evaluate_contact<Scalar>(f, a, nullptr, c);
    } else {
      const BodyMotion<Scalar> b = body_motion(f.key.body_b, q, v, rotations);
      evaluate_contact<Scalar>(f, a, &b, c);
    }
    this->name_contact(naming, c);
    c.friction = material_.friction;
    c.restitution = material_.restitution;
  }
}

// Inlined into the loops over the contacts, as the lambda it replaced was.
template <typename Scalar>
[[gnu::always_inline]] inline BodyMotion<Scalar> PlanarRigidBodySystem<Scalar>::body_motion(
    int i, const Vector& q, const Vector& v, BodyRotations<Scalar>& rotations) const {
  if (i < 0 || i >= num_bodies())
    detail::fail("contact feature names body " + std::to_string(i) + " of " +
                 std::to_string(num_bodies()));
  BodyMotion<Scalar> m;
  m.centre = q.template segment<2>(3 * i);
  const auto body = static_cast<std::size_t>(i);
  if (!rotations.formed[body]) {
    rotations.rotations[body] = rotation(q(3 * i + 2));
    rotations.formed[body] = 1;
  }
  m.rotation = rotations.rotations[body];
  m.velocity = v.template segment<2>(3 * i);
  m.omega = v(3 * i + 2);
  m.first_velocity = 3 * i;
  return m;
}

template <typename Scalar>
void PlanarRigidBodySystem<Scalar>::find_contact_gaps(const Vector& q, const Vector& v,
                                                      double margin,
                                                      std::vector<ContactGap>& out) const {
  check_sizes(q, &v);
  thread_local std::vector<ContactFeature> features;  // storage kept between calls
  detect_features(q, margin, {}, features);
  thread_local BodyRotations<Scalar> rotations;
  rotations.reset(bodies_.size());
  out.clear();
  for (const ContactFeature& f : features) {
    const BodyMotion<Scalar> a = body_motion(f.key.body_a, q, v, rotations);
    Scalar gap;
    if (f.key.body_b < 0) {
      gap = feature_normal<Scalar>(f, feature_points<Scalar>(f, a, nullptr), nullptr).gap;
    } else {
      const BodyMotion<Scalar> b = body_motion(f.key.body_b, q, v, rotations);
      gap = feature_normal<Scalar>(f, feature_points<Scalar>(f, a, &b), &b).gap;
    }
    out.push_back({f.key, value_of(gap)});
  }
}

template <typename Scalar>
void PlanarRigidBodySystem<Scalar>::write_contact_name(const ContactKey& key,
                                                       std::string& name) const {
  const bool known = key.body_a >= 0 && key.body_a < num_bodies() && key.body_b < num_bodies() &&
                     (key.body_b >= 0 || (key.feature >= 0 && key.feature / kFeaturesPerPlane <
                                                                  static_cast<int>(lines_.size())));
  if (!known) [[unlikely]]
    detail::fail("no contact has the key " + key_text(key));
  // Room for any contact's name at once: a slot's contacts change, and a name longer than the
  // slot's room would allocate again in a later step.
  if (name.capacity() < contact_name_capacity_) name.reserve(contact_name_capacity_);
  const int per_line = line_features_of(key.body_a);
  const int line = key.feature / kFeaturesPerPlane, local = key.feature % kFeaturesPerPlane;
  if (key.body_b >= 0 || local >= per_line) return compose_contact_name(key, name);
  name = line_contact_names_[line_name_offset_[static_cast<std::size_t>(key.body_a)] +
                             static_cast<std::size_t>(line * per_line + local)];
}

template <typename Scalar>
void PlanarRigidBodySystem<Scalar>::compose_contact_name(const ContactKey& key,
                                                         std::string& name) const {
  // "<a>-<b>", plus "#<feature>" when a polygon is involved (which has several features):
  // "ball0-ball1", "ball-ground", "block-ground#2", "ball-block#5", "box1-box0#4".
  const bool static_b = key.body_b < 0;
  const std::string& b_name =
      static_b ? lines_[static_cast<std::size_t>(key.feature / kFeaturesPerPlane)].name
               : names_[static_cast<std::size_t>(key.body_b)];
  const bool polygon = !properties_[static_cast<std::size_t>(key.body_a)].disk ||
                       (!static_b && !properties_[static_cast<std::size_t>(key.body_b)].disk);
  write_pair_name(names_[static_cast<std::size_t>(key.body_a)], b_name, name);
  if (polygon)
    name.append("#").append(
        std::to_string(static_b ? key.feature % kFeaturesPerPlane : key.feature));
}

}  // namespace impactbench::model::planar
