#include "tools/engines/fixed_step/reference_scene.hpp"

namespace impactbench::adapters {

std::vector<std::pair<int, Eigen::Vector3d>> input_forces(const ReferenceScene& scene, double t) {
  std::vector<std::pair<int, Eigen::Vector3d>> forces;
  if (!scene.input) return forces;
  const Eigen::VectorXd u = scene.input(t);
  for (std::size_t j = 0; j < scene.inputs.size(); ++j) {
    const auto& in = scene.inputs[j];
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      if (scene.bodies[i].name == in.body)
        forces.emplace_back(static_cast<int>(i), u[static_cast<Eigen::Index>(j)] * in.direction);
  }
  return forces;
}

const HingeSpec* hinge_of(const ReferenceScene& scene, int body) {
  for (const HingeSpec& hinge : scene.hinges)
    if (hinge.body == body) return &hinge;
  return nullptr;
}

double hinge_torque(const HingeSpec& hinge, double angle, double rate) {
  return -hinge.stiffness * angle - hinge.damping * rate;
}

}  // namespace impactbench::adapters
