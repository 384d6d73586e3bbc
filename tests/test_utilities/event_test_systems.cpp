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

}  // namespace impactbench::test_utilities
