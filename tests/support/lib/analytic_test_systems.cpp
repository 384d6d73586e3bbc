#include "tests/support/lib/analytic_test_systems.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "lib/output/column_names.hpp"

namespace impactbench::test_support {
namespace {

// Jacobian row of the velocity of a body point (arm ρ from the centre) along direction d:
// d·(v + ω ẑ × ρ) = d·v + ω (ρ_x d_y − ρ_y d_x).
Eigen::RowVector3d planar_row(const Eigen::Vector2d& arm, const Eigen::Vector2d& d) {
  return {d.x(), d.y(), arm.x() * d.y() - arm.y() * d.x()};
}

Eigen::Vector2d rotate(double angle, const Eigen::Vector2d& p) {
  return Eigen::Rotation2Dd(angle) * p;
}

}  // namespace

double PlanarTestBody::inertia() const {
  if (radius > 0.0) return 0.5 * mass * radius * radius;
  return mass * (width * width + height * height) / 12.0;
}

PlanarTestWorld::PlanarTestWorld(std::vector<PlanarTestBody> bodies, double gravity,
                                 double friction, double restitution, bool has_ground,
                                 double ground_angle)
    : bodies_(std::move(bodies)),
      gravity_(gravity),
      friction_(friction),
      restitution_(restitution),
      has_ground_(has_ground),
      ground_angle_(ground_angle) {}

void PlanarTestWorld::add_input(int body, const Eigen::Vector2d& direction) {
  input_bodies_.push_back(body);
  input_directions_.push_back(direction);
}

Eigen::Vector2d PlanarTestWorld::ground_normal() const {
  return {-std::sin(ground_angle_), std::cos(ground_angle_)};
}
Eigen::Vector2d PlanarTestWorld::ground_tangent() const {
  return {std::cos(ground_angle_), std::sin(ground_angle_)};
}

PlanarTestWorld::SparseMatrix PlanarTestWorld::mass_matrix(const Vector&) const {
  SparseMatrix M(num_velocities(), num_velocities());
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < num_bodies(); ++i) {
    t.emplace_back(3 * i, 3 * i, bodies_[i].mass);
    t.emplace_back(3 * i + 1, 3 * i + 1, bodies_[i].mass);
    t.emplace_back(3 * i + 2, 3 * i + 2, bodies_[i].inertia());
  }
  M.setFromTriplets(t.begin(), t.end());
  return M;
}

PlanarTestWorld::Vector PlanarTestWorld::bias_forces(const Vector&, const Vector&) const {
  Vector H = Vector::Zero(num_velocities());
  for (int i = 0; i < num_bodies(); ++i) H(3 * i + 1) = bodies_[i].mass * gravity_;
  return H;
}

PlanarTestWorld::Matrix PlanarTestWorld::input_matrix(const Vector&) const {
  Matrix S = Matrix::Zero(num_velocities(), num_inputs());
  for (int k = 0; k < num_inputs(); ++k)
    S.block(3 * input_bodies_[k], k, 2, 1) = input_directions_[k];
  return S;
}

PlanarTestWorld::Vector PlanarTestWorld::position_rate(const Vector&, const Vector& v) const {
  return v;
}

PlanarTestWorld::Vector PlanarTestWorld::integrate_position(const Vector& q, const Vector& v,
                                                            const double& h) const {
  return q + h * v;
}

model::Contact<double> PlanarTestWorld::point_contact(int body, const Eigen::Vector2d& centre,
                                                      const Eigen::Vector2d& arm,
                                                      const Eigen::Vector2d& normal, double gap,
                                                      int feature, std::string name) const {
  model::Contact<double> c;
  c.key = {body, -1, feature};
  c.name = std::move(name);
  c.gap = gap;
  const Eigen::Vector2d tangent(normal.y(), -normal.x());
  model::JacobianBlock<double> block;
  block.first_velocity = 3 * body;
  block.rows.resize(2, 3);
  block.rows.row(0) = planar_row(arm, normal);
  block.rows.row(1) = planar_row(arm, tangent);
  c.blocks.push_back(std::move(block));
  c.tangent_drift = Vector::Zero(1);  // set by the caller where the event tests need it
  c.friction = friction_;
  c.restitution = restitution_;
  c.point = Eigen::Vector3d(centre.x() + arm.x(), centre.y() + arm.y(), 0.0);
  c.normal = Eigen::Vector3d(normal.x(), normal.y(), 0.0);
  return c;
}

void PlanarTestWorld::find_contacts(const Vector& q, const Vector& v, double margin,
                                    std::vector<model::Contact<double>>& out) const {
  out.clear();
  const Eigen::Vector2d n = ground_normal();
  for (int i = 0; has_ground_ && i < num_bodies(); ++i) {
    const Eigen::Vector2d centre = q.segment<2>(3 * i);
    const auto& b = bodies_[i];
    if (b.radius > 0.0) {
      const double gap = n.dot(centre) - b.radius;
      if (gap < margin)
        out.push_back(point_contact(i, centre, -b.radius * n, n, gap, 0, b.name + "-ground"));
      continue;
    }
    for (int corner = 0; corner < 4; ++corner) {
      const Eigen::Vector2d local((corner & 1 ? 0.5 : -0.5) * b.width,
                                  (corner & 2 ? 0.5 : -0.5) * b.height);
      const Eigen::Vector2d arm = rotate(q(3 * i + 2), local);
      const double gap = n.dot(centre + arm);
      if (!(gap < margin)) continue;
      out.push_back(point_contact(i, centre, arm, n, gap, corner,
                                  b.name + "-ground-" + std::to_string(corner)));
      // A body-fixed corner accelerates centripetally by −ω² arm on top of v̇ + ω̇ arm⊥ (the
      // event-driven flow needs these drifts; a disk's contact point has none: its arm −r n
      // does not turn).
      const double omega_squared = v(3 * i + 2) * v(3 * i + 2);
      out.back().normal_drift = -omega_squared * n.dot(arm);
      out.back().tangent_drift(0) = -omega_squared * ground_tangent().dot(arm);
    }
  }
  // Disk–disk pairs; normal from b to a (towards body a), relative velocity of a w.r.t. b.
  for (int a = 0; a < num_bodies(); ++a) {
    for (int b = a + 1; b < num_bodies(); ++b) {
      if (!(bodies_[a].radius > 0.0 && bodies_[b].radius > 0.0)) continue;
      const Eigen::Vector2d d = q.segment<2>(3 * a) - q.segment<2>(3 * b);
      const double dist = d.norm();
      const double gap = dist - bodies_[a].radius - bodies_[b].radius;
      if (gap >= margin) continue;
      const Eigen::Vector2d normal = d / dist;
      const Eigen::Vector2d tangent(normal.y(), -normal.x());
      model::Contact<double> c;
      c.key = {a, b, 0};
      c.name = bodies_[a].name + "-" + bodies_[b].name;
      c.gap = gap;
      model::JacobianBlock<double> ba, bb;
      ba.first_velocity = 3 * a;
      ba.rows.resize(2, 3);
      ba.rows.row(0) = planar_row(-bodies_[a].radius * normal, normal);
      ba.rows.row(1) = planar_row(-bodies_[a].radius * normal, tangent);
      bb.first_velocity = 3 * b;
      bb.rows.resize(2, 3);
      bb.rows.row(0) = -planar_row(bodies_[b].radius * normal, normal);
      bb.rows.row(1) = -planar_row(bodies_[b].radius * normal, tangent);
      c.blocks = {ba, bb};
      c.tangent_drift = Vector::Zero(1);
      c.friction = friction_;
      c.restitution = restitution_;
      out.push_back(std::move(c));
    }
  }
}

double PlanarTestWorld::energy(const Vector& q, const Vector& v) const {
  double e = 0.0;
  for (int i = 0; i < num_bodies(); ++i) {
    const auto& b = bodies_[i];
    e += 0.5 * b.mass * v.segment<2>(3 * i).squaredNorm() +
         0.5 * b.inertia() * v(3 * i + 2) * v(3 * i + 2) + b.mass * gravity_ * q(3 * i + 1);
  }
  return e;
}

std::vector<std::string> PlanarTestWorld::position_names() const {
  return output::rigid_body_position_names(body_names(), false);
}
std::vector<std::string> PlanarTestWorld::velocity_names() const {
  return output::rigid_body_velocity_names(body_names(), false);
}
std::vector<std::string> PlanarTestWorld::body_names() const {
  std::vector<std::string> names;
  for (const auto& b : bodies_) names.push_back(b.name);
  return names;
}

SphereOnPlaneTestSystem::SphereOnPlaneTestSystem(double radius, double mass, double gravity,
                                                 double friction, double restitution)
    : radius_(radius),
      mass_(mass),
      gravity_(gravity),
      friction_(friction),
      restitution_(restitution) {}

SphereOnPlaneTestSystem::SparseMatrix SphereOnPlaneTestSystem::mass_matrix(const Vector&) const {
  SparseMatrix M(6, 6);
  const double inertia = 0.4 * mass_ * radius_ * radius_;
  for (int i = 0; i < 6; ++i) M.insert(i, i) = i < 3 ? mass_ : inertia;
  return M;
}

// An isotropic body has no gyroscopic term: H is gravity alone.
SphereOnPlaneTestSystem::Vector SphereOnPlaneTestSystem::bias_forces(const Vector&,
                                                                     const Vector&) const {
  Vector H = Vector::Zero(6);
  H(2) = mass_ * gravity_;
  return H;
}

SphereOnPlaneTestSystem::Vector SphereOnPlaneTestSystem::position_rate(const Vector& q,
                                                                       const Vector& v) const {
  Vector rate(7);
  rate.head<3>() = v.head<3>();
  const Eigen::Quaterniond quat(q(3), q(4), q(5), q(6));
  const Eigen::Quaterniond omega(0.0, v(3), v(4), v(5));
  const Eigen::Quaterniond d = omega * quat;  // q̇ = ½ ω ⊗ q for a world-frame ω
  rate.tail<4>() << 0.5 * d.w(), 0.5 * d.x(), 0.5 * d.y(), 0.5 * d.z();
  return rate;
}

SphereOnPlaneTestSystem::Vector SphereOnPlaneTestSystem::integrate_position(const Vector& q,
                                                                            const Vector& v,
                                                                            const double& h) const {
  Vector out(7);
  out.head<3>() = q.head<3>() + h * v.head<3>();
  const Eigen::Vector3d w = v.tail<3>();
  const double angle = w.norm() * h;
  const Eigen::Quaterniond turn = angle > 0.0
                                      ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, w.normalized()))
                                      : Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond result =
      (turn * Eigen::Quaterniond(q(3), q(4), q(5), q(6))).normalized();
  out.tail<4>() << result.w(), result.x(), result.y(), result.z();
  return out;
}

void SphereOnPlaneTestSystem::find_contacts(const Vector& q, const Vector&, double margin,
                                            std::vector<model::Contact<double>>& out) const {
  out.clear();
  const double gap = q(2) - radius_;
  if (gap >= margin) return;
  model::Contact<double> c;
  c.key = {0, -1, 0};
  c.name = "sphere-ground";
  c.gap = gap;
  const Eigen::Vector3d arm(0.0, 0.0, -radius_);
  model::JacobianBlock<double> block;
  block.first_velocity = 0;
  block.rows.resize(3, 6);
  const Eigen::Matrix3d dirs = Eigen::Matrix3d::Identity();
  const int order[3] = {2, 0, 1};  // normal ẑ, then tangents x̂, ŷ
  for (int r = 0; r < 3; ++r) {
    const Eigen::Vector3d d = dirs.col(order[r]);
    block.rows.row(r).head<3>() = d.transpose();
    block.rows.row(r).tail<3>() = arm.cross(d).transpose();  // d·(ω × ρ) = ω·(ρ × d)
  }
  c.blocks.push_back(std::move(block));
  c.tangent_drift = Vector::Zero(2);
  c.friction = friction_;
  c.restitution = restitution_;
  c.point = q.head<3>() + arm;
  c.normal = Eigen::Vector3d::UnitZ();
  out.push_back(std::move(c));
}

double SphereOnPlaneTestSystem::energy(const Vector& q, const Vector& v) const {
  const double inertia = 0.4 * mass_ * radius_ * radius_;
  return 0.5 * mass_ * v.head<3>().squaredNorm() + 0.5 * inertia * v.tail<3>().squaredNorm() +
         mass_ * gravity_ * q(2);
}

std::vector<std::string> SphereOnPlaneTestSystem::position_names() const {
  return {"sphere.x", "sphere.y", "sphere.z", "sphere.qw", "sphere.qx", "sphere.qy", "sphere.qz"};
}
std::vector<std::string> SphereOnPlaneTestSystem::velocity_names() const {
  return {"sphere.vx", "sphere.vy", "sphere.vz", "sphere.wx", "sphere.wy", "sphere.wz"};
}

SpringMassFloorTestSystem::SpringMassFloorTestSystem(double mass, double stiffness, double damping,
                                                     double rest_height, double gravity,
                                                     double restitution)
    : mass_(mass),
      stiffness_(stiffness),
      damping_(damping),
      rest_height_(rest_height),
      gravity_(gravity),
      restitution_(restitution) {}

SpringMassFloorTestSystem::SparseMatrix SpringMassFloorTestSystem::mass_matrix(
    const Vector&) const {
  SparseMatrix M(2, 2);
  M.insert(0, 0) = mass_;
  M.insert(1, 1) = mass_;
  return M;
}

SpringMassFloorTestSystem::Vector SpringMassFloorTestSystem::bias_forces(const Vector& q,
                                                                         const Vector& v) const {
  return Eigen::Vector2d(0.0,
                         mass_ * gravity_ + stiffness_ * (q(1) - rest_height_) + damping_ * v(1));
}

void SpringMassFloorTestSystem::find_contacts(const Vector& q, const Vector&, double margin,
                                              std::vector<model::Contact<double>>& out) const {
  out.clear();
  if (q(1) >= margin) return;
  model::Contact<double> c;
  c.key = {0, -1, 0};
  c.name = "mass-floor";
  c.gap = q(1);
  model::JacobianBlock<double> block;
  block.first_velocity = 0;
  block.rows = Eigen::Matrix2d{{0.0, 1.0}, {1.0, 0.0}};
  c.blocks.push_back(std::move(block));
  c.tangent_drift = Vector::Zero(1);
  c.restitution = restitution_;
  out.push_back(std::move(c));
}

double SpringMassFloorTestSystem::energy(const Vector& q, const Vector& v) const {
  const double stretch = q(1) - rest_height_;
  return 0.5 * mass_ * v.squaredNorm() + 0.5 * stiffness_ * stretch * stretch +
         mass_ * gravity_ * q(1);
}

}  // namespace impactbench::test_support
