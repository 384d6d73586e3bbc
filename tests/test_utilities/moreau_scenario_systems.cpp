#include "moreau_scenario_systems.hpp"

#include "lib/model/planar/planar_system.hpp"
#include "lib/model/plank_box/plank_box_system.hpp"
#include "lib/model/spatial/spatial_system.hpp"
#include "lib/scenario/plank_box_scenario.hpp"

namespace impactbench::testing {

ScenarioSystem make_scenario_system(const scenario::Scenario& s) {
  ScenarioSystem out;
  if (s.system == scenario::SystemKind::kPlankBox) {
    const auto initial = scenario::plank_box_initial_state(s);
    out.system = std::make_unique<model::PlankBoxSystem<double>>(scenario::plank_box_parameters(s));
    out.q0 = initial.q;
    out.v0 = initial.v;
  } else if (s.dimension == scenario::Dimension::kPlanar) {
    auto system = std::make_unique<model::planar::PlanarRigidBodySystemd>(
        s.bodies, s.planes, -s.gravity.y(), s.material, s.inputs);
    out.q0 = system->initial_positions();
    out.v0 = system->initial_velocities();
    out.system = std::move(system);
  } else {
    model::spatial::SpatialSystemSpec spec;
    spec.bodies = s.bodies;
    spec.planes = s.planes;
    spec.material = s.material;
    spec.gravity = -s.gravity.z();
    spec.inputs = s.inputs;
    auto system = std::make_unique<model::spatial::SpatialRigidBodySystem<double>>(spec);
    out.q0 = system->initial_positions();
    out.v0 = system->initial_velocities();
    out.system = std::move(system);
  }
  return out;
}

}  // namespace impactbench::testing
