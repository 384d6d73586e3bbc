#include "lib/sensitivity/reported_coordinates.hpp"

#include <utility>

#include "lib/metrics/pose_error.hpp"

namespace impactbench::sensitivity {

ComposedGain reported_gain(const HybridModel& model, const ConewiseJumpGain& event,
                           ComposedGain gain) {
  if (!model.has_tangent_coordinates()) return gain;
  const Eigen::MatrixXd P = model.tangent_projection(gain.x_plus);
  gain.Gz = P * gain.Gz * model.tangent_basis(event.x_minus());
  gain.Gv = P * gain.Gv;
  return gain;
}

EndPointSensitivity reported_end_point(const TrajectorySensitivity& sensitivity,
                                       EndPointSensitivity end_point) {
  const HybridModel& model = sensitivity.model();
  if (!model.has_tangent_coordinates()) return end_point;
  const Eigen::MatrixXd P = model.tangent_projection(sensitivity.segments().back().alpha.back());
  end_point.state = P * end_point.state * model.tangent_basis(sensitivity.nominal().x0);
  end_point.input = P * end_point.input;
  return end_point;
}

std::vector<std::string> reported_state_names(const HybridModel& model,
                                              const std::vector<std::string>& position_names,
                                              const std::vector<std::string>& velocity_names,
                                              int parameters) {
  std::vector<std::string> names;
  // Where the quaternions are (pose_layout checks each is b.qw b.qx b.qy b.qz in a row).
  const std::vector<int> quaternions = model.has_tangent_coordinates()
                                           ? metrics::pose_layout(position_names).quaternions
                                           : std::vector<int>{};
  auto next_quaternion = quaternions.begin();
  for (std::size_t i = 0; i < position_names.size(); ++i) {
    if (next_quaternion == quaternions.end() || static_cast<std::size_t>(*next_quaternion) != i) {
      names.push_back(position_names[i]);
      continue;
    }
    // b.qw b.qx b.qy b.qz → b.rx b.ry b.rz
    const std::string& name = position_names[i];
    const std::string body = name.substr(0, name.size() - 3);
    for (const char* axis : {".rx", ".ry", ".rz"}) names.push_back(body + axis);
    i += 3;
    ++next_quaternion;
  }
  names.insert(names.end(), velocity_names.begin(), velocity_names.end());
  if (parameters == 2)
    for (const char* name : {"friction", "restitution"}) names.emplace_back(name);
  return names;
}

}  // namespace impactbench::sensitivity
