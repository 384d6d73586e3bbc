#pragma once
// Everything that defines a spatial rigid-body system: bodies (spheres and cuboids, z up),
// static planes, the contact material, gravity and the input channels.
#include <vector>

#include "lib/model/body_spec.hpp"

namespace impactbench::model::spatial {

struct SpatialSystemSpec {
  std::vector<BodySpec> bodies;         ///< shape kSphere or kCuboid
  std::vector<StaticPlaneSpec> planes;  ///< floor, walls; unit outward normals
  Material material;
  double gravity = 9.81;  ///< [m/s²] along −z
  std::vector<ForceInputSpec> inputs;
};

/// Throws std::invalid_argument naming the body/plane/input and the field when the spec is not
/// usable: mass, radius or sizes not finite and > 0, non-unit orientation or plane normal,
/// non-finite state, planar shapes, duplicate or empty names, μ < 0, e ∉ [0, 1], unknown input
/// body.
void validate(const SpatialSystemSpec& spec);

}  // namespace impactbench::model::spatial
