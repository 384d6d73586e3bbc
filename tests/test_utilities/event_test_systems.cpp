#include "event_test_systems.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace impactbench::test_utilities {
namespace {

Eigen::SparseMatrix<double> diagonal(const Eigen::VectorXd& d) {
  Eigen::SparseMatrix<double> M(d.size(), d.size());
  for (Eigen::Index i = 0; i < d.size(); ++i) M.insert(i, i) = d[i];
  M.makeCompressed();
  return M;
}

Eigen::Vector2d perp(const Eigen::Vector2d& r) {
  return {-r.y(), r.x()};
}

}  // namespace

EventPlanarBody EventPlanarBody::disk(double radius, double mass, const EventTestGround& ground) {
  EventPlanarBody b;
  b.mass = mass;
  b.inertia = 0.5 * mass * radius * radius;
  b.rounding = radius;
  b.points = {Eigen::Vector2d::Zero()};
  b.ground = ground;
  return b;
}

EventPlanarBody EventPlanarBody::box(double width, double height, double mass,
                                     const EventTestGround& ground) {
  EventPlanarBody b;
  b.mass = mass;
  b.inertia = mass * (width * width + height * height) / 12.0;
  b.points = {{-width / 2, -height / 2},
              {width / 2, -height / 2},
              {width / 2, height / 2},
              {-width / 2, height / 2}};
  b.ground = ground;
  return b;
}

EventPlanarBody::SparseMatrix EventPlanarBody::mass_matrix(const Vector&) const {
  return diagonal(Eigen::Vector3d(mass, mass, inertia));
}

EventPlanarBody::Vector EventPlanarBody::bias_forces(const Vector&, const Vector&) const {
  return Eigen::Vector3d(0.0, mass * ground.gravity, 0.0);
}

EventPlanarBody::Matrix EventPlanarBody::input_matrix(const Vector&) const {
  return Eigen::Vector3d(input_direction.x(), input_direction.y(), 0.0);
}

EventPlanarBody::Vector EventPlanarBody::position_rate(const Vector&, const Vector& v) const {
  return v;
}

EventPlanarBody::Vector EventPlanarBody::integrate_position(const Vector& q, const Vector& v,
                                                            const double& h) const {
  return q + h * v;
}

void EventPlanarBody::find_contacts(const Vector& q, const Vector& v, double margin,
                                    std::vector<model::Contact<double>>& out) const {
  out.clear();
  const Eigen::Vector2d n = ground.normal, t = ground.tangent();
  const Eigen::Rotation2Dd R(q[2]);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector2d arm = R * points[k];       // centre → point
    const Eigen::Vector2d rho = arm - rounding * n;  // centre → contact point
    const double gap = n.dot(q.head<2>() + arm - ground.point) - rounding;
    if (gap > margin) continue;
    model::Contact<double> c;
    c.key = {0, -1, static_cast<int>(k)};
    c.name = points.size() == 1 ? "disk-ground" : "corner" + std::to_string(k);
    c.gap = gap;
    model::JacobianBlock<double> block;
    block.first_velocity = 0;
    block.rows.resize(2, 3);
    block.rows.row(0) << n.x(), n.y(), n.dot(perp(rho));
    block.rows.row(1) << t.x(), t.y(), t.dot(perp(rho));
    c.blocks.push_back(block);
    const double omega = v[2];
    c.normal_drift = -omega * omega * n.dot(arm);  // d/dt of ρ⊥ is −ω·arm
    c.tangent_drift = Eigen::VectorXd::Constant(1, -omega * omega * t.dot(arm));
    c.friction = ground.friction;
    c.restitution = ground.restitution;
    const Eigen::Vector2d point = q.head<2>() + rho;
    c.point = Eigen::Vector3d(point.x(), point.y(), 0.0);
    c.normal = Eigen::Vector3d(n.x(), n.y(), 0.0);
    out.push_back(std::move(c));
  }
}

double EventPlanarBody::energy(const Vector& q, const Vector& v) const {
  return 0.5 * mass * v.head<2>().squaredNorm() + 0.5 * inertia * v[2] * v[2] +
         mass * ground.gravity * q[1];
}

std::vector<std::string> EventPlanarBody::position_names() const {
  return {"body.x", "body.y", "body.theta"};
}
std::vector<std::string> EventPlanarBody::velocity_names() const {
  return {"body.vx", "body.vy", "body.omega"};
}

EventSpatialBall::SparseMatrix EventSpatialBall::mass_matrix(const Vector&) const {
  Eigen::VectorXd d(6);
  d << mass, mass, mass, inertia(), inertia(), inertia();
  return diagonal(d);
}

EventSpatialBall::Vector EventSpatialBall::bias_forces(const Vector&, const Vector&) const {
  Eigen::VectorXd h = Eigen::VectorXd::Zero(6);
  h[2] = mass * gravity;  // a sphere has no gyroscopic term
  return h;
}

EventSpatialBall::Vector EventSpatialBall::position_rate(const Vector& q, const Vector& v) const {
  Eigen::VectorXd qdot(7);
  qdot.head<3>() = v.head<3>();
  const Eigen::Quaterniond orientation(q[3], q[4], q[5], q[6]);
  const Eigen::Quaterniond omega(0.0, v[3], v[4], v[5]);
  const Eigen::Quaterniond rate = omega * orientation;  // q̇ = ½ ω ⊗ q, ω in the world frame
  qdot.tail<4>() << 0.5 * rate.w(), 0.5 * rate.x(), 0.5 * rate.y(), 0.5 * rate.z();
  return qdot;
}

EventSpatialBall::Vector EventSpatialBall::integrate_position(const Vector& q, const Vector& v,
                                                              const double& h) const {
  Eigen::VectorXd out(7);
  out.head<3>() = q.head<3>() + h * v.head<3>();
  const Eigen::Vector3d rotation = h * v.tail<3>();
  const double angle = rotation.norm();
  const Eigen::Quaterniond step =
      angle > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation / angle))
                  : Eigen::Quaterniond::Identity();
  Eigen::Quaterniond orientation = step * Eigen::Quaterniond(q[3], q[4], q[5], q[6]);
  orientation.normalize();
  out.tail<4>() << orientation.w(), orientation.x(), orientation.y(), orientation.z();
  return out;
}

void EventSpatialBall::find_contacts(const Vector& q, const Vector&, double margin,
                                     std::vector<model::Contact<double>>& out) const {
  out.clear();
  const double gap = q[2] - radius;
  if (gap > margin) return;
  model::Contact<double> c;
  c.key = {0, -1, 0};
  c.name = "ball-ground";
  c.gap = gap;
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d rho = -radius * n;  // centre → contact point
  model::JacobianBlock<double> block;
  block.first_velocity = 0;
  block.rows.resize(3, 6);
  block.rows.row(0) << n.transpose(), Eigen::RowVector3d::Zero();
  const Eigen::Vector3d t1 = Eigen::Vector3d::UnitX(), t2 = Eigen::Vector3d::UnitY();
  block.rows.row(1) << t1.transpose(), rho.cross(t1).transpose();  // t·(ω × ρ) = ω·(ρ × t)
  block.rows.row(2) << t2.transpose(), rho.cross(t2).transpose();
  c.blocks.push_back(block);
  c.normal_drift = 0.0;
  c.tangent_drift = Eigen::VectorXd::Zero(2);
  c.friction = friction;
  c.restitution = restitution;
  c.point = q.head<3>() + rho;
  c.normal = n;
  out.push_back(std::move(c));
}

double EventSpatialBall::energy(const Vector& q, const Vector& v) const {
  return 0.5 * mass * v.head<3>().squaredNorm() + 0.5 * inertia() * v.tail<3>().squaredNorm() +
         mass * gravity * q[2];
}

std::vector<std::string> EventSpatialBall::position_names() const {
  return {"ball.x", "ball.y", "ball.z", "ball.qw", "ball.qx", "ball.qy", "ball.qz"};
}
std::vector<std::string> EventSpatialBall::velocity_names() const {
  return {"ball.vx", "ball.vy", "ball.vz", "ball.wx", "ball.wy", "ball.wz"};
}

}  // namespace impactbench::test_utilities
