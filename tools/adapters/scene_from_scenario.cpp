#include "tools/adapters/scene_from_scenario.hpp"

namespace impactbench::adapters {

ReferenceScene make_reference_scene(const scenario::Scenario& scenario, const RunOptions& options) {
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
  scene.duration = options.duration.value_or(scenario.duration);
  scene.dt = options.dt.value_or(scenario.dt);
  return scene;
}

}  // namespace impactbench::adapters
