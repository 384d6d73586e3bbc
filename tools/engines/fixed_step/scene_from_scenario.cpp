#include "tools/engines/fixed_step/scene_from_scenario.hpp"

#include <cmath>
#include <memory>

#include "lib/engines/system_builder.hpp"
#include "lib/scenario/plank_box_scenario.hpp"

namespace impactbench::adapters {

ReferenceScene make_reference_scene(const scenario::Scenario& scenario, double duration,
                                    double dt) {
  ReferenceScene scene;
  scene.planar = scenario.dimension == scenario::Dimension::kPlanar;
  scene.bodies = scenario.bodies;
  scene.planes = scenario.planes;
  scene.material = scenario.material;
  scene.gravity = scenario.gravity.norm();
  scene.inputs = scenario.inputs;
  if (!scenario.inputs.empty()) scene.input = [s = scenario](double t) { return s.input(t); };
  if (scenario.system == scenario::SystemKind::kPlankBox) {
    // The plank turns about its left end (x = 0 when level), held by the hinge's spring and
    // damper; the box is free and the plank's top face its only contact.
    const model::PlankBoxParameters p = scenario::plank_box_parameters(scenario);
    for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i) {
      const model::BodySpec& plank = scene.bodies[i];
      if (plank.name != "plank") continue;
      const Eigen::Vector3d half(p.plank_length / 2 * std::cos(plank.angle),
                                 p.plank_length / 2 * std::sin(plank.angle), 0.0);
      scene.hinges.push_back({i, plank.position - half, p.plank_stiffness, p.plank_damping});
    }
  }
  scene.duration = duration;
  scene.dt = dt;
  // Energy by our own model of the same bodies, so every engine's energy column is comparable.
  std::shared_ptr<const model::LagrangianSystem<double>> system =
      engines::build_system(scenario).system;
  scene.energy = [system](const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    return system->energy(q, v);
  };
  return scene;
}

}  // namespace impactbench::adapters
