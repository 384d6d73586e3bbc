#include "lib/validation/toss_score.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lib/metrics/pose_error.hpp"
#include "lib/metrics/trajectory_error.hpp"

namespace impactbench::validation {
namespace {

std::size_t column(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw std::invalid_argument("simulated trajectory has no column '" + name + "'");
  return static_cast<std::size_t>(it - names.begin());
}

void check_sizes(const Toss& data, std::size_t start, const std::vector<SimulatedPose>& simulated,
                 const char* caller) {
  if (start >= data.samples.size() || simulated.size() != data.samples.size() - start)
    throw std::invalid_argument(std::string(caller) + ": " + std::to_string(simulated.size()) +
                                " simulated states for " + std::to_string(data.samples.size()) +
                                " samples from sample " + std::to_string(start));
}

SampleError error_at(const TossSample& d, const SimulatedPose& s, double side, double t0) {
  return {d.t - t0, (s.position - d.position).norm() / side,
          metrics::rotation_distance(s.orientation, d.orientation)};
}

}  // namespace

const std::vector<std::string>& score_names() {
  static const std::vector<std::string> names = {
      "position",      "rotation",      "velocity",          "angular_velocity",
      "rest_position", "rest_rotation", "first_contact_time"};
  return names;
}

std::vector<double> score_values(const TossScore& s) {
  return {s.position,      s.rotation,      s.velocity,          s.angular_velocity,
          s.rest_position, s.rest_rotation, s.first_contact_time};
}

TossScore score_toss(const Toss& data, std::size_t start,
                     const std::vector<SimulatedPose>& simulated, const CubeGeometry& cube) {
  check_sizes(data, start, simulated, "score_toss");
  TossScore score;
  const double n = static_cast<double>(simulated.size());
  std::size_t sim_contact = simulated.size();
  for (std::size_t i = 0; i < simulated.size(); ++i) {
    const TossSample& d = data.samples[start + i];
    const SimulatedPose& s = simulated[i];
    const SampleError error = error_at(d, s, cube.side, 0.0);
    score.position += error.position / n;
    score.rotation += error.rotation / n;
    score.velocity += (s.velocity - d.velocity).norm() / n;
    score.angular_velocity += (s.angular_velocity - d.angular_velocity_world()).norm() / n;
    if (sim_contact == simulated.size() &&
        lowest_corner_height(s.position, s.orientation, cube.side) <=
            cube.board_offset + cube.contact_margin)
      sim_contact = i;
  }
  const TossSample& last = data.samples.back();
  score.rest_position = (simulated.back().position - last.position).norm();
  score.rest_rotation = metrics::rotation_distance(simulated.back().orientation, last.orientation);
  const auto contact_time = [&](std::size_t k) {
    return data.samples[std::min(k, data.samples.size() - 1)].t;
  };
  const std::size_t data_contact = std::max(first_contact_index(data, cube), start);
  score.first_contact_time =
      std::abs(contact_time(start + sim_contact) - contact_time(data_contact));
  return score;
}

std::vector<SampleError> sample_errors(const Toss& data, std::size_t start,
                                       const std::vector<SimulatedPose>& simulated,
                                       const CubeGeometry& cube) {
  check_sizes(data, start, simulated, "sample_errors");
  std::vector<SampleError> errors;
  errors.reserve(simulated.size());
  for (std::size_t i = 0; i < simulated.size(); ++i)
    errors.push_back(
        error_at(data.samples[start + i], simulated[i], cube.side, data.samples[start].t));
  return errors;
}

std::vector<SimulatedPose> poses_at_samples(const output::Trajectory& trajectory,
                                            const std::string& body, const Toss& data,
                                            std::size_t start) {
  if (trajectory.samples.empty())
    throw std::invalid_argument("simulated trajectory has no samples");
  const auto& q = trajectory.position_names;
  const auto& v = trajectory.velocity_names;
  const std::size_t x = column(q, body + ".x"), qw = column(q, body + ".qw");
  const std::size_t vx = column(v, body + ".vx"), wx = column(v, body + ".wx");
  metrics::Signal signal;
  Eigen::Vector4d previous = Eigen::Vector4d::Zero();
  for (const auto& sample : trajectory.samples) {
    Eigen::VectorXd state(13);  // position, quaternion (w first), velocity, angular velocity
    Eigen::Vector4d quaternion = sample.q.segment<4>(static_cast<Eigen::Index>(qw));
    if (quaternion.dot(previous) < 0) quaternion = -quaternion;  // sign-continuous
    previous = quaternion;
    state << sample.q.segment<3>(static_cast<Eigen::Index>(x)), quaternion,
        sample.v.segment<3>(static_cast<Eigen::Index>(vx)),
        sample.v.segment<3>(static_cast<Eigen::Index>(wx));
    signal.times.push_back(sample.t);
    signal.values.push_back(state);
  }
  std::vector<SimulatedPose> poses;
  const double t0 = data.samples.at(start).t;
  for (std::size_t k = start; k < data.samples.size(); ++k) {
    const Eigen::VectorXd s = signal.at(data.samples[k].t - t0);
    SimulatedPose pose;
    pose.position = s.segment<3>(0);
    pose.orientation = Eigen::Quaterniond(s(3), s(4), s(5), s(6)).normalized();
    pose.velocity = s.segment<3>(7);
    pose.angular_velocity = s.segment<3>(10);
    poses.push_back(pose);
  }
  return poses;
}

}  // namespace impactbench::validation
