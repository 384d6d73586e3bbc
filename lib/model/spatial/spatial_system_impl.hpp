#pragma once
// Definitions of SpatialRigidBodySystem<Scalar>; included only by the .cpp files that
// instantiate it (double, autodiff).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/SparseCore>

#include "lib/model/body_inertia.hpp"
#include "lib/model/body_reach.hpp"
#include "lib/model/broad_phase/overlapping_pair_cache.hpp"
#include "lib/model/broad_phase/uniform_grid.hpp"
#include "lib/model/contact_name.hpp"
#include "lib/model/contact_prefetch.hpp"
#include "lib/model/contact_storage.hpp"
#include "lib/model/spatial/pair_geometry.hpp"
#include "lib/model/spatial/spatial_system.hpp"
#include "lib/model/spatial/tangent_frame.hpp"
#include "lib/output/column_names.hpp"

namespace impactbench::model::spatial {
namespace detail {

template <typename Scalar, typename VectorType>
BodyState<Scalar> body_state(const VectorType& q, const VectorType& v, int body) {
  BodyState<Scalar> s;
  s.position = q.template segment<3>(7 * body);
  s.rotation = rotation_matrix<Scalar>(q.template segment<4>(7 * body + 3));
  s.linear_velocity = v.template segment<3>(6 * body);
  s.angular_velocity = v.template segment<3>(6 * body + 3);
  return s;
}

/// The rows (n, t1, t2) of one body's 3 x 6 Jacobian block for directions d through the arm r:
/// dᵀ(v + ω × r) = [dᵀ, (r × d)ᵀ] (v, ω).
template <typename Scalar>
void jacobian_block(int body, const Vector3<Scalar> (&directions)[3], const Vector3<Scalar>& arm,
                    const Scalar& sign, JacobianBlock<Scalar>& block) {
  block.first_velocity = 6 * body;
  block.rows.resize(3, 6);
  for (int k = 0; k < 3; ++k) {
    block.rows.row(k).template head<3>() = sign * directions[k].transpose();
    block.rows.row(k).template tail<3>() = sign * arm.cross(directions[k]).transpose();
  }
}

/// Fills c (its storage reused: no allocation once a contact slot has been used) from the pair
/// geometry (see pair_geometry.hpp for the drift formula). The name is set by the caller.
template <typename Scalar>
void assemble_contact(const PairGeometry<Scalar>& g, const BodyState<Scalar>& a,
                      const BodyState<Scalar>* b, ContactKey key, const Material& material,
                      Contact<Scalar>& c) {
  const TangentFrame<Scalar> frame = tangent_frame(g.normal, g.normal_rate);
  const Vector3<Scalar> directions[3] = {g.normal, frame.t1, frame.t2};
  const Vector3<Scalar> rates[3] = {g.normal_rate, frame.t1_rate, frame.t2_rate};

  Vector3<Scalar> u = a.linear_velocity + a.angular_velocity.cross(g.arm_a);
  Vector3<Scalar> arm_term = a.angular_velocity.cross(g.arm_a_rate);
  if (b != nullptr) {
    u -= b->linear_velocity + b->angular_velocity.cross(g.arm_b);
    arm_term -= b->angular_velocity.cross(g.arm_b_rate);
  }

  c.key = key;
  c.gap = g.gap;
  c.blocks.reserve(2);  // room for two bodies at once: a slot's one-body contact may become two
  resize_blocks(c.blocks, b != nullptr ? 2 : 1);
  jacobian_block(key.body_a, directions, g.arm_a, Scalar(1), c.blocks[0]);
  if (b != nullptr) jacobian_block(key.body_b, directions, g.arm_b, Scalar(-1), c.blocks[1]);
  c.normal_drift = rates[0].dot(u) + directions[0].dot(arm_term);
  c.tangent_drift.resize(2);
  for (int k = 1; k < 3; ++k)
    c.tangent_drift(k - 1) = rates[k].dot(u) + directions[k].dot(arm_term);
  c.friction = material.friction;
  c.restitution = material.restitution;
  c.point = values_of<Scalar>(a.position + g.arm_a);
  c.normal = values_of<Scalar>(g.normal);
}

}  // namespace detail

template <typename Scalar>
SpatialRigidBodySystem<Scalar>::SpatialRigidBodySystem(SpatialSystemSpec spec)
    : spec_(std::move(spec)) {
  validate(spec_);
  for (const BodySpec& b : spec_.bodies) body_inertia_.push_back(principal_inertia(b));
}

template <typename Scalar>
void SpatialRigidBodySystem<Scalar>::fail_sizes(const Vector& q, const Vector* v) const {
  if (q.size() != num_positions())
    throw std::invalid_argument("spatial system: q has " + std::to_string(q.size()) +
                                " entries, expected " + std::to_string(num_positions()));
  throw std::invalid_argument("spatial system: v has " + std::to_string(v->size()) +
                              " entries, expected " + std::to_string(num_velocities()));
}

template <typename Scalar>
Matrix3<Scalar> SpatialRigidBodySystem<Scalar>::world_inertia(int body,
                                                              const Matrix3<Scalar>& R) const {
  return R * body_inertia_[body].cast<Scalar>().asDiagonal() * R.transpose();
}

template <typename Scalar>
auto SpatialRigidBodySystem<Scalar>::mass_matrix(const Vector& q) const -> SparseMatrix {
  SparseMatrix M;
  write_mass_matrix(q, M);
  return M;
}

template <typename Scalar>
void SpatialRigidBodySystem<Scalar>::write_mass_matrix(const Vector& q_in, SparseMatrix& M) const {
  check_sizes(q_in, nullptr);
  const auto& q = coherent(q_in, derivative_count(q_in));
  // Column by column, rows ascending: per body m on the three linear diagonal entries, then the
  // world inertia's 3 × 3 block (its zeros stored too), written into the compressed arrays
  // (12 entries a body, storage kept from call to call).
  M.resize(num_velocities(), num_velocities());
  M.resizeNonZeros(12 * static_cast<Eigen::Index>(num_bodies()));
  int* outer = M.outerIndexPtr();
  int* inner = M.innerIndexPtr();
  Scalar* values = M.valuePtr();
  int entry = 0;
  const auto add = [&](int row, const Scalar& value) {
    inner[entry] = row;
    values[entry++] = value;
  };
  for (int i = 0; i < num_bodies(); ++i) {
    const Scalar m(spec_.bodies[i].mass);
    for (int k = 0; k < 3; ++k) {
      outer[6 * i + k] = entry;
      add(6 * i + k, m);
    }
    const Matrix3<Scalar> I =
        world_inertia(i, rotation_matrix<Scalar>(q.template segment<4>(7 * i + 3)));
    for (int c = 0; c < 3; ++c) {
      outer[6 * i + 3 + c] = entry;
      for (int r = 0; r < 3; ++r) add(6 * i + 3 + r, I(r, c));
    }
  }
  outer[num_velocities()] = entry;
}

template <typename Scalar>
auto SpatialRigidBodySystem<Scalar>::bias_forces(const Vector& q, const Vector& v) const -> Vector {
  Vector H;
  write_bias_forces(q, v, H);
  return H;
}

template <typename Scalar>
void SpatialRigidBodySystem<Scalar>::write_bias_forces(const Vector& q_in, const Vector& v_in,
                                                       Vector& H) const {
  check_sizes(q_in, &v_in);
  const Eigen::Index nd = std::max(derivative_count(q_in), derivative_count(v_in));
  const auto& q = coherent(q_in, nd);
  const auto& v = coherent(v_in, nd);
  H.setZero(num_velocities());
  for (int i = 0; i < num_bodies(); ++i) {
    H(6 * i + 2) = Scalar(spec_.bodies[i].mass * spec_.gravity);
    const Vector3<Scalar> w = v.template segment<3>(6 * i + 3);
    const Matrix3<Scalar> I =
        world_inertia(i, rotation_matrix<Scalar>(q.template segment<4>(7 * i + 3)));
    H.template segment<3>(6 * i + 3) = w.cross(I * w);
  }
}

template <typename Scalar>
auto SpatialRigidBodySystem<Scalar>::input_matrix(const Vector& q) const -> Matrix {
  check_sizes(q, nullptr);
  Matrix S = Matrix::Zero(num_velocities(), num_inputs());
  for (int k = 0; k < num_inputs(); ++k) {
    const ForceInputSpec& in = spec_.inputs[k];
    int body = 0;
    while (spec_.bodies[body].name != in.body) ++body;  // validate() guarantees it exists
    S.col(k).template segment<3>(6 * body) = in.direction.cast<Scalar>();
  }
  return S;
}

template <typename Scalar>
auto SpatialRigidBodySystem<Scalar>::position_rate(const Vector& q_in, const Vector& v_in) const
    -> Vector {
  check_sizes(q_in, &v_in);
  const Eigen::Index nd = std::max(derivative_count(q_in), derivative_count(v_in));
  const auto& q = coherent(q_in, nd);
  const auto& v = coherent(v_in, nd);
  Vector rate(num_positions());
  for (int i = 0; i < num_bodies(); ++i) {
    rate.template segment<3>(7 * i) = v.template segment<3>(6 * i);
    rate.template segment<4>(7 * i + 3) =
        quaternion_rate<Scalar>(q.template segment<4>(7 * i + 3), v.template segment<3>(6 * i + 3));
  }
  return rate;
}

template <typename Scalar>
auto SpatialRigidBodySystem<Scalar>::integrate_position(const Vector& q, const Vector& v,
                                                        const Scalar& h) const -> Vector {
  Vector next;
  write_integrated_position(q, v, h, next);
  return next;
}

template <typename Scalar>
void SpatialRigidBodySystem<Scalar>::write_integrated_position(const Vector& q_in,
                                                               const Vector& v_in,
                                                               const Scalar& h_in,
                                                               Vector& next) const {
  check_sizes(q_in, &v_in);
  Eigen::Index nd = std::max(derivative_count(q_in), derivative_count(v_in));
  Scalar h = h_in;
  if constexpr (IsAutoDiff<Scalar>::value) {
    const Vector h_vector = Vector::Constant(1, h_in);
    nd = std::max(nd, derivative_count(h_vector));
    h = coherent(h_vector, nd)(0);
  }
  const auto& q = coherent(q_in, nd);
  const auto& v = coherent(v_in, nd);
  next.resize(num_positions());
  for (int i = 0; i < num_bodies(); ++i) {
    next.template segment<3>(7 * i) =
        q.template segment<3>(7 * i) + h * v.template segment<3>(6 * i);
    next.template segment<4>(7 * i + 3) = integrate_quaternion<Scalar>(
        q.template segment<4>(7 * i + 3), v.template segment<3>(6 * i + 3), h);
  }
}

template <typename Scalar>
void SpatialRigidBodySystem<Scalar>::find_contacts(const Vector& q, const Vector& v, double margin,
                                                   std::vector<Contact<Scalar>>& out) const {
  find_contacts_within(q, v, margin, {}, ContactNaming::kNamed, out);
}

template <typename Scalar>
bool SpatialRigidBodySystem<Scalar>::find_reachable_contacts(
    const Vector& q, const Vector& v, const Eigen::VectorXd& speed_bound, double horizon,
    double margin, std::vector<Contact<Scalar>>& out) const {
  thread_local std::vector<double> reach;  // storage kept between calls
  body_reaches(
      speed_bound, horizon, num_bodies(), 3, 3,
      [&](int i) {
        return spec_.bodies[i].shape == ShapeKind::kSphere ? spec_.bodies[i].radius
                                                           : half_extents(i).norm();
      },
      [&](int i) { return spec_.bodies[i].name; }, "spatial find_contacts: ", reach);
  find_contacts_within(q, v, margin, reach, ContactNaming::kUnnamed, out);
  return true;
}

template <typename Scalar>
void SpatialRigidBodySystem<Scalar>::write_contact_name(const ContactKey& key,
                                                        std::string& name) const {
  // The keys find_contacts_within gives: (i, j, 0) for a pair, the sphere first when one of
  // them is a cuboid; (i, −1, p) for a sphere on plane p; (i, −1, 8p + corner) for a cuboid's
  // corner on plane p.
  const auto& bodies = spec_.bodies;
  const int n = num_bodies();
  const int planes = static_cast<int>(spec_.planes.size());
  const bool body_a = key.body_a >= 0 && key.body_a < n;
  const bool sphere_a = body_a && bodies[key.body_a].shape == ShapeKind::kSphere;
  const int plane = sphere_a ? key.feature : key.feature / 8;
  const bool known = body_a && key.body_b < n &&
                     (key.body_b >= 0 ? key.feature == 0 : key.feature >= 0 && plane < planes);
  if (!known) [[unlikely]]
    throw std::invalid_argument("spatial contact name: no contact has the key " + key_text(key));
  if (key.body_b >= 0)
    return write_pair_name(bodies[key.body_a].name, bodies[key.body_b].name, name);
  write_pair_name(bodies[key.body_a].name, spec_.planes[plane].name, name);
  if (!sphere_a) name.append("#").append(std::to_string(key.feature % 8));
}

template <typename Scalar>
void SpatialRigidBodySystem<Scalar>::find_contacts_within(const Vector& q_in, const Vector& v_in,
                                                          double margin,
                                                          std::span<const double> reach_of_body,
                                                          ContactNaming naming,
                                                          std::vector<Contact<Scalar>>& out) const {
  check_sizes(q_in, &v_in);
  if (!reach_of_body.empty() && reach_of_body.size() != spec_.bodies.size())
    throw std::invalid_argument("spatial find_contacts: reach has " +
                                std::to_string(reach_of_body.size()) + " entries for " +
                                std::to_string(spec_.bodies.size()) + " bodies");
  const auto extra = [&](int i) {
    return reach_of_body.empty() ? 0.0 : reach_of_body[static_cast<std::size_t>(i)];
  };
  const Eigen::Index nd = std::max(derivative_count(q_in), derivative_count(v_in));
  const auto& q = coherent(q_in, nd);
  const auto& v = coherent(v_in, nd);
  if (!(margin >= 0.0)) throw std::invalid_argument("spatial find_contacts: margin must be >= 0");
  // Contacts are written over the slots of `out` (their strings and blocks keep their storage)
  // and `out` is cut to the number found at the end.
  std::size_t found = 0;
  const auto next_contact = [&]() -> Contact<Scalar>& {
    if (found == out.size()) append_contact(out);
    prefetch_contact_storage<Scalar>(out, found);
    return out[found++];
  };
  const int n = num_bodies();
  // Scratch kept per thread between calls, as the broad phase's.
  thread_local std::vector<BodyState<Scalar>> states;
  states.clear();
  for (int i = 0; i < n; ++i) states.push_back(detail::body_state<Scalar>(q, v, i));
  const auto is_sphere = [&](int i) { return spec_.bodies[i].shape == ShapeKind::kSphere; };
  const auto& bodies = spec_.bodies;

  // Body pairs from the broad phase, in its sorted order.
  thread_local std::vector<Aabb> boxes;
  boxes.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d centre = values_of<Scalar>(states[i].position);
    Eigen::Vector3d reach;
    if (is_sphere(i)) {
      reach.setConstant(bodies[i].radius);
    } else {
      Eigen::Matrix3d R;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) R(r, c) = value_of(states[i].rotation(r, c));
      reach = R.cwiseAbs() * half_extents(i);
    }
    reach.array() += 0.5 * margin + extra(i);
    boxes[i].min = centre - reach;
    boxes[i].max = centre + reach;
  }
  // The grid's pairs kept across calls while the bodies stay within the cache's skin.
  thread_local OverlappingPairCache pair_cache;
  thread_local OverlappingPairs pairs;  // storage kept between calls
  pair_cache.find(boxes, pairs);
  for (const auto& [i, j] : pairs) {
    if (is_sphere(i) && is_sphere(j)) {
      const PairGeometry<Scalar> g =
          sphere_sphere(states[i], bodies[i].radius, states[j], bodies[j].radius);
      if (value_of(g.gap) < margin + extra(i) + extra(j)) {
        Contact<Scalar>& c = next_contact();
        detail::assemble_contact<Scalar>(g, states[i], &states[j], {i, j, 0}, spec_.material, c);
        this->name_contact(naming, c);
      }
    } else if (is_sphere(i) || is_sphere(j)) {
      const int s = is_sphere(i) ? i : j;
      const int b = is_sphere(i) ? j : i;
      const PairGeometry<Scalar> g =
          sphere_cuboid(states[s], bodies[s].radius, states[b], half_extents(b));
      if (value_of(g.gap) < margin + extra(i) + extra(j)) {
        Contact<Scalar>& c = next_contact();
        detail::assemble_contact<Scalar>(g, states[s], &states[b], {s, b, 0}, spec_.material, c);
        this->name_contact(naming, c);
      }
    } else {
      throw std::runtime_error("spatial find_contacts: cuboid-cuboid contact between '" +
                               bodies[i].name + "' and '" + bodies[j].name +
                               "' is not implemented");
    }
  }

  // Every body against every plane.
  for (int i = 0; i < n; ++i) {
    const double plane_margin = margin + extra(i);
    for (int p = 0; p < static_cast<int>(spec_.planes.size()); ++p) {
      const StaticPlaneSpec& plane = spec_.planes[p];
      if (is_sphere(i)) {
        const PairGeometry<Scalar> g =
            sphere_plane(states[i], bodies[i].radius, plane.point, plane.normal);
        if (value_of(g.gap) < plane_margin) {
          Contact<Scalar>& c = next_contact();
          detail::assemble_contact<Scalar>(g, states[i], nullptr, {i, -1, p}, spec_.material, c);
          this->name_contact(naming, c);
        }
        continue;
      }
      const double centre_height =
          plane.normal.dot(values_of<Scalar>(states[i].position) - plane.point);
      if (centre_height - half_extents(i).norm() >= plane_margin)
        continue;  // no corner can be near
      for (int corner = 0; corner < 8; ++corner) {
        const PairGeometry<Scalar> g =
            cuboid_corner_plane(states[i], half_extents(i), corner, plane.point, plane.normal);
        if (value_of(g.gap) < plane_margin) {
          Contact<Scalar>& c = next_contact();
          detail::assemble_contact<Scalar>(g, states[i], nullptr, {i, -1, 8 * p + corner},
                                           spec_.material, c);
          this->name_contact(naming, c);
        }
      }
    }
  }
  resize_contacts(out, found);
}

template <typename Scalar>
Scalar SpatialRigidBodySystem<Scalar>::energy(const Vector& q_in, const Vector& v_in) const {
  check_sizes(q_in, &v_in);
  const Eigen::Index nd = std::max(derivative_count(q_in), derivative_count(v_in));
  const auto& q = coherent(q_in, nd);
  const auto& v = coherent(v_in, nd);
  Scalar e(0);
  for (int i = 0; i < num_bodies(); ++i) {
    const double m = spec_.bodies[i].mass;
    const Vector3<Scalar> lin = v.template segment<3>(6 * i);
    const Vector3<Scalar> w = v.template segment<3>(6 * i + 3);
    const Matrix3<Scalar> I =
        world_inertia(i, rotation_matrix<Scalar>(q.template segment<4>(7 * i + 3)));
    e += Scalar(0.5 * m) * lin.squaredNorm() + Scalar(0.5) * w.dot(I * w) +
         Scalar(m * spec_.gravity) * q(7 * i + 2);
  }
  return e;
}

template <typename Scalar>
std::vector<std::string> SpatialRigidBodySystem<Scalar>::position_names() const {
  return output::rigid_body_position_names(spec_.bodies, true);
}

template <typename Scalar>
std::vector<std::string> SpatialRigidBodySystem<Scalar>::velocity_names() const {
  return output::rigid_body_velocity_names(spec_.bodies, true);
}

template <typename Scalar>
auto SpatialRigidBodySystem<Scalar>::initial_positions() const -> Vector {
  Vector q(num_positions());
  for (int i = 0; i < num_bodies(); ++i) {
    const BodySpec& b = spec_.bodies[i];
    const Eigen::Quaterniond o = b.orientation.normalized();
    q.template segment<3>(7 * i) = b.position.cast<Scalar>();
    q.template segment<4>(7 * i + 3) << Scalar(o.w()), Scalar(o.x()), Scalar(o.y()), Scalar(o.z());
  }
  return q;
}

template <typename Scalar>
auto SpatialRigidBodySystem<Scalar>::initial_velocities() const -> Vector {
  Vector v(num_velocities());
  for (int i = 0; i < num_bodies(); ++i) {
    v.template segment<3>(6 * i) = spec_.bodies[i].velocity.cast<Scalar>();
    v.template segment<3>(6 * i + 3) = spec_.bodies[i].angular_velocity.cast<Scalar>();
  }
  return v;
}

}  // namespace impactbench::model::spatial
