#include "lib/metrics/pose_error.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace impactbench::metrics {
namespace {

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() > tail.size() &&
         text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

Eigen::Quaterniond quaternion_at(const Eigen::VectorXd& q, int at) {
  return Eigen::Quaterniond(q[at], q[at + 1], q[at + 2], q[at + 3]);
}

// Flips each sample's quaternions to the sign nearer the previous sample's, so that linear
// interpolation between samples stays near the unit sphere.
Signal sign_continuous(Signal signal, const PoseLayout& layout) {
  for (std::size_t i = 1; i < signal.values.size(); ++i)
    for (const int at : layout.quaternions)
      if (signal.values[i].segment<4>(at).dot(signal.values[i - 1].segment<4>(at)) < 0.0)
        signal.values[i].segment<4>(at) *= -1.0;
  return signal;
}

}  // namespace

PoseLayout pose_layout(const std::vector<std::string>& names) {
  PoseLayout layout;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string& name = names[i];
    const int at = static_cast<int>(i);
    if (ends_with(name, ".x") || ends_with(name, ".y") || ends_with(name, ".z")) {
      layout.positions.push_back(at);
    } else if (ends_with(name, ".theta") || ends_with(name, ".phi")) {
      layout.angles.push_back(at);
    } else if (ends_with(name, ".qw")) {
      const std::string body = name.substr(0, name.size() - 3);
      if (i + 3 >= names.size() || names[i + 1] != body + ".qx" || names[i + 2] != body + ".qy" ||
          names[i + 3] != body + ".qz")
        throw std::invalid_argument("pose_layout: '" + name +
                                    "' is not followed by its qx, qy, qz columns");
      layout.quaternions.push_back(at);
      i += 3;
    } else {
      throw std::invalid_argument("pose_layout: column '" + name +
                                  "' is neither a position, an angle nor a quaternion");
    }
  }
  return layout;
}

double rotation_distance(double theta_a, double theta_b) {
  return std::abs(std::remainder(theta_a - theta_b, 2.0 * std::numbers::pi));
}

double rotation_distance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  // The relative rotation a b⁻¹ has angle 2 atan2(‖vec‖, |w|); |w| picks the shorter of the
  // two quaternions of the rotation. Normalising makes interpolated quaternions exact rotations.
  const Eigen::Quaterniond r = a.normalized() * b.normalized().conjugate();
  return 2.0 * std::atan2(r.vec().norm(), std::abs(r.w()));
}

PoseTrajectoryError pose_trajectory_error(const Signal& trajectory, const Signal& reference,
                                          const PoseLayout& layout) {
  const auto position = [&layout](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    double sum = 0.0;
    for (const int i : layout.positions) sum += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(sum);
  };
  const auto orientation = [&layout](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    double sum = 0.0;
    for (const int i : layout.angles) sum += std::pow(rotation_distance(a[i], b[i]), 2);
    for (const int i : layout.quaternions)
      sum += std::pow(rotation_distance(quaternion_at(a, i), quaternion_at(b, i)), 2);
    return std::sqrt(sum);
  };
  const Signal continuous = sign_continuous(reference, layout);
  return {trajectory_error(trajectory, continuous, position),
          trajectory_error(trajectory, continuous, orientation)};
}

}  // namespace impactbench::metrics
