#pragma once
// Free spatial rigid bodies (spheres, cuboids) among static planes, z up, gravity along −z.
//
// Coordinates per body i (7 positions from 7i, 6 velocities from 6i):
//   q_i = (x, y, z, qw, qx, qy, qz)  centre and unit quaternion (body → world)
//   v_i = (vx, vy, vz, wx, wy, wz)   centre velocity and WORLD-frame angular velocity ω
// so q̇_i = N(q) v_i with ṗ = v, q̇uat = ½ (0, ω) ⊗ quat.
//
// Dynamics in the form M v̇ + H = S u + Σ w λ of lagrangian_system.hpp, per body
//   M_i = diag(m I₃, I_w),  I_w = R I_body Rᵀ,
//   H_i = (0, 0, m g, ω × I_w ω).
// The gyroscopic term follows from d/dt(I_w ω) = τ with İ_w = [ω]× I_w − I_w [ω]×, whence
// İ_w ω = ω × I_w ω.
//
// Contacts (pair_geometry.hpp): sphere–plane, cuboid corner–plane (one contact per corner,
// feature = 8·plane + corner), sphere–sphere, sphere–cuboid. Cuboid–cuboid pairs are not
// implemented: find_contacts throws when two cuboids' bounding boxes come within the margin,
// rather than silently missing a contact. Pairs of bodies are found by the uniform-grid broad
// phase on bounding boxes inflated by margin/2 each (its pairs kept across calls while the
// bodies stay within a skin: overlapping_pair_cache.hpp); planes are tested against every body.
//
// ContactKey: body_a is the body the normal points to (the sphere of a sphere–cuboid pair, the
// lower index of a sphere pair); body_b = −1 for planes, with feature = plane index (spheres) or
// 8·plane index + corner (cuboids); feature = 0 for body pairs. Contact::point is the witness
// point on body a; the one on body b is point − gap·normal.
#include <span>
#include <string>
#include <vector>

#include "lib/model/lagrangian_system.hpp"
#include "lib/model/spatial/quaternion_kinematics.hpp"
#include "lib/model/spatial/spatial_system_spec.hpp"

namespace impactbench::model::spatial {

template <typename Scalar>
class SpatialRigidBodySystem final : public LagrangianSystem<Scalar> {
 public:
  using typename LagrangianSystem<Scalar>::Vector;
  using typename LagrangianSystem<Scalar>::Matrix;
  using typename LagrangianSystem<Scalar>::SparseMatrix;

  static constexpr int kPositionsPerBody = 7;
  static constexpr int kVelocitiesPerBody = 6;

  /// Validates the spec (see validate()) and throws std::invalid_argument on bad input.
  explicit SpatialRigidBodySystem(SpatialSystemSpec spec);

  int num_positions() const override { return kPositionsPerBody * num_bodies(); }
  int num_velocities() const override { return kVelocitiesPerBody * num_bodies(); }
  int num_inputs() const override { return static_cast<int>(spec_.inputs.size()); }
  int tangent_dim() const override { return 2; }
  int num_bodies() const { return static_cast<int>(spec_.bodies.size()); }
  const SpatialSystemSpec& spec() const { return spec_; }

  SparseMatrix mass_matrix(const Vector& q) const override;
  void write_mass_matrix(const Vector& q, SparseMatrix& M) const override;
  Vector bias_forces(const Vector& q, const Vector& v) const override;
  void write_bias_forces(const Vector& q, const Vector& v, Vector& out) const override;
  Matrix input_matrix(const Vector& q) const override;
  Vector position_rate(const Vector& q, const Vector& v) const override;
  Vector integrate_position(const Vector& q, const Vector& v, const Scalar& h) const override;
  void write_integrated_position(const Vector& q, const Vector& v, const Scalar& h,
                                 Vector& out) const override;
  void find_contacts(const Vector& q, const Vector& v, double margin,
                     std::vector<Contact<Scalar>>& out) const override;
  /// Bodies reach h (|s_v| + |s_ω| r) beyond the margin, r a sphere's radius or a cuboid's
  /// half diagonal.
  bool find_reachable_contacts(const Vector& q, const Vector& v, const Eigen::VectorXd& speed_bound,
                               double horizon, double margin,
                               std::vector<Contact<Scalar>>& out) const override;
  void write_contact_name(const ContactKey& key, std::string& name) const override;
  Scalar energy(const Vector& q, const Vector& v) const override;
  std::vector<std::string> position_names() const override;
  std::vector<std::string> velocity_names() const override;

  /// The state the spec describes.
  Vector initial_positions() const;
  Vector initial_velocities() const;

 private:
  Eigen::Vector3d half_extents(int body) const { return 0.5 * spec_.bodies[body].size; }
  Matrix3<Scalar> world_inertia(int body, const Matrix3<Scalar>& rotation) const;
  // Inline, as it runs on every call of the hot paths; the message is built out of line.
  void check_sizes(const Vector& q, const Vector* v) const {
    if (q.size() != num_positions() || (v != nullptr && v->size() != num_velocities())) [[unlikely]]
      fail_sizes(q, v);
  }
  [[noreturn]] void fail_sizes(const Vector& q, const Vector* v) const;
  /// find_contacts with the margin of every pair and plane widened by the reach of its bodies
  /// (one distance per body [m], or empty).
  void find_contacts_within(const Vector& q, const Vector& v, double margin,
                            std::span<const double> reach, ContactNaming naming,
                            std::vector<Contact<Scalar>>& out) const;

  SpatialSystemSpec spec_;
  std::vector<Eigen::Vector3d> body_inertia_;  ///< principal moments in the body frame
};

extern template class SpatialRigidBodySystem<double>;

}  // namespace impactbench::model::spatial
