#include "lib/engines/system_builder.hpp"

#include "lib/engines/autodiff_system_builder.hpp"
#include "lib/model/planar/planar_system_autodiff.hpp"
#include "lib/model/plank_box/plank_box_system.hpp"
#include "lib/model/spatial/spatial_system_autodiff.hpp"
#include "lib/scenario/plank_box_scenario.hpp"

namespace impactbench::engines {
namespace {

// Each kind of system on either scalar: one construction for the engines (double) and the
// sensitivity module's Jacobians (AD).
template <typename Scalar>
auto make_plank_box(const scenario::Scenario& s) {
  return std::make_unique<model::PlankBoxSystem<Scalar>>(scenario::plank_box_parameters(s));
}

template <typename Scalar>
auto make_planar(const scenario::Scenario& s) {
  return std::make_unique<model::planar::PlanarRigidBodySystem<Scalar>>(
      s.bodies, s.planes, s.gravity.norm(), s.material, s.inputs);
}

template <typename Scalar>
auto make_spatial(const scenario::Scenario& s) {
  return std::make_unique<model::spatial::SpatialRigidBodySystem<Scalar>>(spatial_spec(s));
}

/// Rigid bodies start from their specs' positions, orientations and velocities.
template <typename System>
BuiltSystem with_initial_state(std::unique_ptr<System> system) {
  Eigen::VectorXd q = system->initial_positions(), v = system->initial_velocities();
  return {std::move(system), std::move(q), std::move(v)};
}

}  // namespace

model::spatial::SpatialSystemSpec spatial_spec(const scenario::Scenario& s) {
  return {s.bodies, s.planes, s.material, s.gravity.norm(), s.inputs};
}

BuiltSystem build_system(const scenario::Scenario& scenario) {
  if (scenario.system == scenario::SystemKind::kPlankBox) {
    const auto state = scenario::plank_box_initial_state(scenario);
    return {make_plank_box<double>(scenario), state.q, state.v};
  }
  if (scenario.dimension == scenario::Dimension::kPlanar)
    return with_initial_state(make_planar<double>(scenario));
  return with_initial_state(make_spatial<double>(scenario));
}

std::unique_ptr<const model::LagrangianSystem<model::AutoDiff>> build_autodiff_system(
    const scenario::Scenario& scenario) {
  if (scenario.system == scenario::SystemKind::kPlankBox)
    return make_plank_box<model::AutoDiff>(scenario);
  if (scenario.dimension == scenario::Dimension::kPlanar)
    return make_planar<model::AutoDiff>(scenario);
  return make_spatial<model::AutoDiff>(scenario);
}

}  // namespace impactbench::engines
