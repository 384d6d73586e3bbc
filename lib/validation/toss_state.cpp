#include "lib/validation/toss_state.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

namespace impactbench::validation {
namespace {

/// Rotation vector (axis × angle, angle in [0, π]) of a unit quaternion.
Eigen::Vector3d rotation_vector(Eigen::Quaterniond q) {
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const Eigen::AngleAxisd aa(q);
  return aa.angle() * aa.axis();
}

Eigen::Quaterniond from_rotation_vector(const Eigen::Vector3d& r) {
  const double angle = r.norm();
  if (angle == 0.0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, r / angle));
}

}  // namespace

double lowest_corner_height(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                            double side) {
  const Eigen::Matrix3d R = orientation.toRotationMatrix();
  return position.z() - side / 2 * R.row(2).cwiseAbs().sum();
}

std::size_t first_contact_index(const Toss& toss, const CubeGeometry& cube) {
  for (std::size_t k = 0; k < toss.samples.size(); ++k) {
    const auto& s = toss.samples[k];
    if (lowest_corner_height(s.position, s.orientation, cube.side) <=
        cube.board_offset + cube.contact_margin)
      return k;
  }
  return toss.samples.size();
}

InitialState sample_state(const Toss& toss, std::size_t k) {
  if (k >= toss.samples.size())
    throw std::out_of_range(toss.name + ": sample " + std::to_string(k) + " of " +
                            std::to_string(toss.samples.size()));
  const TossSample& s = toss.samples[k];
  return {s.t, s.position, s.orientation, s.velocity, s.angular_velocity_world()};
}

InitialState fitted_state(const Toss& toss, const CubeGeometry& cube, double gravity) {
  const std::size_t n = first_contact_index(toss, cube);
  if (n < 3)
    throw std::runtime_error(toss.name + ": " + std::to_string(n) +
                             " free-flight sample(s) before the first contact; a fit needs 3");
  const auto rows = static_cast<Eigen::Index>(n);
  const TossSample& first = toss.samples.front();
  Eigen::MatrixXd A(rows, 2);
  Eigen::MatrixXd positions(rows, 3), rotations(rows, 3);
  for (Eigen::Index k = 0; k < rows; ++k) {
    const TossSample& s = toss.samples[static_cast<std::size_t>(k)];
    const double tau = s.t - first.t;
    A.row(k) << 1.0, tau;
    positions.row(k) = s.position.transpose();
    positions(k, 2) += 0.5 * gravity * tau * tau;  // the known fall, removed before the fit
    rotations.row(k) = rotation_vector(s.orientation * first.orientation.conjugate()).transpose();
  }
  const auto qr = A.colPivHouseholderQr();
  const Eigen::MatrixXd p = qr.solve(positions);  // rows: value at τ = 0, rate
  const Eigen::MatrixXd r = qr.solve(rotations);
  InitialState state;
  state.t = first.t;
  state.position = p.row(0).transpose();
  state.velocity = p.row(1).transpose();
  state.orientation = (from_rotation_vector(r.row(0).transpose()) * first.orientation).normalized();
  state.angular_velocity = r.row(1).transpose();
  return state;
}

scenario::ParameterOverrides state_parameters(const InitialState& s) {
  return {
      {"x", s.position.x()},         {"y", s.position.y()},          {"z", s.position.z()},
      {"qw", s.orientation.w()},     {"qx", s.orientation.x()},      {"qy", s.orientation.y()},
      {"qz", s.orientation.z()},     {"vx", s.velocity.x()},         {"vy", s.velocity.y()},
      {"vz", s.velocity.z()},        {"wx", s.angular_velocity.x()}, {"wy", s.angular_velocity.y()},
      {"wz", s.angular_velocity.z()}};
}

bool is_state_parameter(const std::string& name) {
  return state_parameters({}).count(name) > 0;
}

}  // namespace impactbench::validation
