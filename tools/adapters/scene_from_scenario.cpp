#include "tools/adapters/scene_from_scenario.hpp"

#include <memory>

#include "lib/engines/system_builder.hpp"

namespace impactbench::adapters {

ReferenceScene make_reference_scene(const scenario::Scenario& scenario, double duration,
                                    double dt) {
  if (scenario.system != scenario::SystemKind::kRigidBodies)
    throw UnsupportedScene("scenario '" + scenario.name + "' is the " +
                           scenario::to_string(scenario.system) +
                           " system, which the reference engines cannot represent");
  ReferenceScene scene;
  scene.planar = scenario.dimension == scenario::Dimension::kPlanar;
  scene.bodies = scenario.bodies;
  scene.planes = scenario.planes;
  scene.material = scenario.material;
  scene.gravity = scenario.gravity.norm();
  scene.inputs = scenario.inputs;
  if (!scenario.inputs.empty()) scene.input = [s = scenario](double t) { return s.input(t); };
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
