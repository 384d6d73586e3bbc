#pragma once
// A static half-space (point + outward normal) as the thin box both reference engines need:
// Bullet is far less faithful with btStaticPlaneShape, and Box2D has no half-space shape.
#include <cmath>

#include <Eigen/Core>

#include "lib/model/body_spec.hpp"

namespace impactbench::adapters {

struct BoundarySlab {
  Eigen::Vector3d centre;        ///< box centre, half a thickness below the surface
  Eigen::Vector3d half_extents;  ///< (along-surface, thickness, along-surface)
  double planar_angle = 0.0;     ///< rotation about z taking +y to the normal (planar)
};

inline BoundarySlab boundary_slab(const model::StaticPlaneSpec& plane, double half_length,
                                  double half_thickness = 1.0) {
  const Eigen::Vector3d n = plane.normal.normalized();
  BoundarySlab slab;
  slab.centre = plane.point - half_thickness * n;
  slab.half_extents = Eigen::Vector3d(half_length, half_thickness, half_length);
  slab.planar_angle = std::atan2(-n.x(), n.y());
  return slab;
}

}  // namespace impactbench::adapters
