#include "lib/engines/system_builder.hpp"

#include "lib/model/planar/planar_system.hpp"
#include "lib/model/plank_box/plank_box_system.hpp"
#include "lib/model/spatial/spatial_system.hpp"
#include "lib/scenario/plank_box_scenario.hpp"

namespace impactbench::engines {
namespace {

BuiltSystem build_planar(const scenario::Scenario& s) {
  auto system = std::make_unique<model::planar::PlanarRigidBodySystem<double>>(
      s.bodies, s.planes, s.gravity.norm(), s.material, s.inputs);
  const int n = static_cast<int>(s.bodies.size());
  Eigen::VectorXd q(3 * n), v(3 * n);
  for (int i = 0; i < n; ++i) {
    const model::BodySpec& b = s.bodies[i];
    q.segment<3>(3 * i) << b.position.x(), b.position.y(), b.angle;
    v.segment<3>(3 * i) << b.velocity.x(), b.velocity.y(), b.angular_velocity.z();
  }
  return {std::move(system), q, v};
}

BuiltSystem build_spatial(const scenario::Scenario& s) {
  model::spatial::SpatialSystemSpec spec{s.bodies, s.planes, s.material, s.gravity.norm(),
                                         s.inputs};
  auto system = std::make_unique<model::spatial::SpatialRigidBodySystem<double>>(std::move(spec));
  Eigen::VectorXd q = system->initial_positions(), v = system->initial_velocities();
  return {std::move(system), q, v};
}

BuiltSystem build_plank_box(const scenario::Scenario& s) {
  const auto state = scenario::plank_box_initial_state(s);
  return {std::make_unique<model::PlankBoxSystem<double>>(scenario::plank_box_parameters(s)),
          state.q, state.v};
}

}  // namespace

BuiltSystem build_system(const scenario::Scenario& scenario) {
  if (scenario.system == scenario::SystemKind::kPlankBox) return build_plank_box(scenario);
  if (scenario.dimension == scenario::Dimension::kPlanar) return build_planar(scenario);
  return build_spatial(scenario);
}

}  // namespace impactbench::engines
