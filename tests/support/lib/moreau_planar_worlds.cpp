#include "tests/support/lib/moreau_planar_worlds.hpp"

#include <cmath>
#include <stdexcept>

#include "lib/model/planar/planar_system.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"

namespace impactbench::test_support {

std::string to_string(PlanarKind kind) {
  return kind == PlanarKind::kProjectSystem ? "PlanarRigidBodySystem" : "PlanarTestWorld";
}

model::BodySpec disk(const std::string& name, double radius, double mass) {
  model::BodySpec b;
  b.name = name;
  b.shape = model::ShapeKind::kDisk;
  b.radius = radius;
  b.mass = mass;
  return b;
}

model::BodySpec box(const std::string& name, double width, double height, double mass) {
  model::BodySpec b;
  b.name = name;
  b.shape = model::ShapeKind::kBox;
  b.size = Eigen::Vector3d(width, height, 0.0);
  b.mass = mass;
  return b;
}

std::unique_ptr<model::LagrangianSystem<double>> make_planar_world(PlanarKind kind,
                                                                   const PlanarWorldSpec& spec) {
  if (kind == PlanarKind::kProjectSystem) {
    std::vector<model::StaticPlaneSpec> planes;
    if (spec.has_ground) {
      model::StaticPlaneSpec ground;
      ground.normal = Eigen::Vector3d(-std::sin(spec.ground_angle), std::cos(spec.ground_angle), 0);
      planes.push_back(ground);
    }
    return std::make_unique<model::planar::PlanarRigidBodySystemd>(
        spec.bodies, planes, spec.gravity, spec.material, spec.inputs);
  }
  std::vector<PlanarTestBody> bodies;
  for (const auto& b : spec.bodies) {
    if (b.shape == model::ShapeKind::kDisk)
      bodies.push_back({b.name, b.mass, b.radius, 0.0, 0.0});
    else
      bodies.push_back({b.name, b.mass, 0.0, b.size.x(), b.size.y()});
  }
  auto world = std::make_unique<PlanarTestWorld>(bodies, spec.gravity, spec.material.friction,
                                                 spec.material.restitution, spec.has_ground,
                                                 spec.ground_angle);
  for (const auto& input : spec.inputs) {
    int index = -1;
    for (std::size_t i = 0; i < spec.bodies.size(); ++i)
      if (spec.bodies[i].name == input.body) index = static_cast<int>(i);
    if (index < 0) throw std::invalid_argument("unknown input body " + input.body);
    world->add_input(index, input.direction.head<2>());
  }
  return world;
}

}  // namespace impactbench::test_support
