#pragma once
// Planar rigid bodies (disks and boxes, the latter as convex polygons) under gravity −g ŷ, with
// static lines as boundaries and force inputs at body centres: the source's B.2 system
//     M v̇ + H = S u + Σ_i (w_n,i λ_n,i + W_t,i λ_t,i),  H = (0, m g, 0) per body,
// q = (x, y, θ) and v = (vx, vy, ω) per body, so q̇ = v.
//
// Contacts: disk–line, polygon–line (one per vertex below the margin), disk–disk, disk–polygon
// and polygon–polygon (separating axis, clipping). The active feature of every contact is
// chosen on the double values of q and then frozen (see contact_feature.hpp for the
// convention); all contact quantities are exact derivatives of the frozen gap functions
// (contact_kinematics.hpp). Candidate body pairs come from the uniform-grid broad phase on
// bounding boxes inflated by the margin, so piles of N similar bodies cost O(N); its pairs are
// kept across calls while the bodies stay within a skin (overlapping_pair_cache.hpp).
//
// Contact keys: body–body (a, b, local feature); body–line (body, −1,
// plane_index * kFeaturesPerPlane + vertex index).
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "lib/model/body_spec.hpp"
#include "lib/model/lagrangian_system.hpp"
#include "lib/model/planar/contact_feature.hpp"
#include "lib/model/planar/contact_kinematics.hpp"
#include "lib/model/planar/convex_polygon.hpp"

namespace impactbench::model::planar {

enum class BroadPhase {
  kUniformGrid,  ///< O(N) for similar-sized bodies (default)
  kAllPairs,     ///< every pair to the narrow phase: the test oracle
};

template <typename Scalar>
class PlanarRigidBodySystem final : public LagrangianSystem<Scalar> {
 public:
  using typename LagrangianSystem<Scalar>::Vector;
  using typename LagrangianSystem<Scalar>::Matrix;
  using typename LagrangianSystem<Scalar>::SparseMatrix;

  /// Throws std::invalid_argument naming the body/plane/input and the field when a value is
  /// invalid (mass ≤ 0 or not finite, radius/size ≤ 0, unknown shape, zero normal, μ < 0,
  /// e ∉ [0, 1], duplicate or unknown body names, gravity not finite).
  PlanarRigidBodySystem(std::vector<BodySpec> bodies, std::vector<StaticPlaneSpec> planes,
                        double gravity, Material material, std::vector<ForceInputSpec> inputs = {});

  int num_positions() const override { return 3 * num_bodies(); }
  int num_velocities() const override { return 3 * num_bodies(); }
  int num_inputs() const override { return static_cast<int>(inputs_.size()); }
  int tangent_dim() const override { return 1; }

  SparseMatrix mass_matrix(const Vector& q) const override;
  bool mass_matrix_is_constant() const override { return true; }   ///< diag(m, m, I) per body
  bool bias_forces_are_constant() const override { return true; }  ///< gravity alone
  Vector bias_forces(const Vector& q, const Vector& v) const override;
  void write_bias_forces(const Vector& q, const Vector& v, Vector& out) const override;
  Matrix input_matrix(const Vector& q) const override;
  Vector position_rate(const Vector& q, const Vector& v) const override;
  void write_position_rate(const Vector& q, const Vector& v, Eigen::Ref<Vector> out) const override;
  Vector integrate_position(const Vector& q, const Vector& v, const Scalar& h) const override;
  void write_integrated_position(const Vector& q, const Vector& v, const Scalar& h,
                                 Vector& out) const override;
  void find_contacts(const Vector& q, const Vector& v, double margin,
                     std::vector<Contact<Scalar>>& out) const override;
  /// detect_features and each feature's gap alone (feature_normal, as evaluate_contact).
  void find_contact_gaps(const Vector& q, const Vector& v, double margin,
                         std::vector<ContactGap>& out) const override;
  /// Bodies reach h (|(s_x, s_y)| + s_ω r) beyond the margin, r the body's bounding radius.
  bool find_reachable_contacts(const Vector& q, const Vector& v, const Eigen::VectorXd& speed_bound,
                               double horizon, double margin,
                               std::vector<Contact<Scalar>>& out) const override;
  /// A body–line contact's name copied from those formed once, any other's composed.
  void write_contact_name(const ContactKey& key, std::string& name) const override;
  Scalar energy(const Vector& q, const Vector& v) const override;
  std::vector<std::string> position_names() const override;
  std::vector<std::string> velocity_names() const override;

  /// The two halves of find_contacts: choose the active features on the values of q (broad and
  /// narrow phase), then evaluate them at any (q, v) with the features frozen. Integrators that
  /// need one smooth gap function over a step (and the finite-difference tests) use these.
  /// `reach` (one distance per body [m], or empty) widens the margin of every pair and line by
  /// the reach of the bodies involved.
  std::vector<ContactFeature> detect_features(const Vector& q, double margin,
                                              std::span<const double> reach = {}) const;
  /// The same into `features` (contents replaced, storage kept), as the steppers call it.
  void detect_features(const Vector& q, double margin, std::span<const double> reach,
                       std::vector<ContactFeature>& features) const;
  void evaluate_features(const std::vector<ContactFeature>& features, const Vector& q,
                         const Vector& v, std::vector<Contact<Scalar>>& out,
                         ContactNaming naming = ContactNaming::kNamed) const;

  int num_bodies() const { return static_cast<int>(bodies_.size()); }
  const BodySpec& body(int i) const { return bodies_[static_cast<std::size_t>(i)].spec; }
  double mass(int i) const { return properties_[static_cast<std::size_t>(i)].mass; }
  double inertia(int i) const { return properties_[static_cast<std::size_t>(i)].inertia; }
  double gravity() const { return gravity_; }
  const Material& material() const { return material_; }

  /// q and v of the specs' initial state.
  Eigen::VectorXd initial_positions() const;
  Eigen::VectorXd initial_velocities() const;

  void set_broad_phase(BroadPhase broad_phase) { broad_phase_ = broad_phase; }
  BroadPhase broad_phase() const { return broad_phase_; }

 private:
  struct Body {
    BodySpec spec;
    ConvexPolygon polygon;  ///< empty for disks
  };
  // The numbers of a body that the passes over all bodies at every step read (energy, forces,
  // bounding boxes, contact names), kept apart from the Body (its spec with name and initial
  // state, its polygon: some 300 bytes): a pass over 10,000 bodies then reads 40 bytes a body.
  struct BodyProperties {
    double mass = 0.0;
    double inertia = 0.0;
    double radius = 0.0;  ///< the spec's
    double bounding_radius = 0.0;
    bool disk = true;
  };
  struct Line {
    std::string name;
    Eigen::Vector2d point;
    Eigen::Vector2d normal;  ///< unit
  };
  struct Input {
    int body = 0;
    Eigen::Vector2d direction;
  };

  // Inline, as it runs on every call of the hot paths; the message is built out of line.
  /// Body i's motion from q and v, its rotation taken from (or formed into) `rotations`.
  [[gnu::always_inline]] BodyMotion<Scalar> body_motion(int i, const Vector& q, const Vector& v,
                                                        BodyRotations<Scalar>& rotations) const;
  void check_sizes(const Vector& q, const Vector* v) const {
    if (q.size() != num_positions() || (v != nullptr && v->size() != num_velocities())) [[unlikely]]
      fail_sizes(q, v);
  }
  [[noreturn]] void fail_sizes(const Vector& q, const Vector* v) const;
  const std::vector<std::string>& body_names() const { return names_; }
  /// The name write_contact_name gives, composed from the names of the two sides.
  void compose_contact_name(const ContactKey& key, std::string& name) const;
  /// Body–line features per line: 1 for a disk, one per vertex for a polygon.
  int line_features_of(int body) const;

  std::vector<Body> bodies_;
  std::vector<BodyProperties> properties_;  // one per body, as bodies_
  std::vector<std::string> names_;          // the bodies' names, apart for the same reason
  std::vector<Line> lines_;
  std::vector<Input> inputs_;
  double gravity_;
  Material material_;
  BroadPhase broad_phase_ = BroadPhase::kUniformGrid;
  // Every body–line contact's name: body i's start at line_name_offset_[i], then
  // line_features_of(i) per line.
  std::vector<std::string> line_contact_names_;
  std::vector<std::size_t> line_name_offset_;
  std::size_t contact_name_capacity_ = 0;  // characters: the longest name a contact can get
};

extern template class PlanarRigidBodySystem<double>;
using PlanarRigidBodySystemd = PlanarRigidBodySystem<double>;

}  // namespace impactbench::model::planar
