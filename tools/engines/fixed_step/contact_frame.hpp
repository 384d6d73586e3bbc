#pragma once
// The tangent frame every reference engine reports friction impulses and sliding velocities in
// (engines::ContactSample): planar scenes the in-plane tangent first, so impulse and velocity
// are compared component by component whatever frame the engine solved in.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace impactbench::adapters {

struct TangentFrame {
  Eigen::Vector3d e1;
  Eigen::Vector3d e2;
  /// (a·e1, a·e2)
  Eigen::Vector2d components(const Eigen::Vector3d& a) const { return {a.dot(e1), a.dot(e2)}; }
};

/// `normal` a unit vector (planar: in the x–y plane).
inline TangentFrame tangent_frame(const Eigen::Vector3d& normal, bool planar) {
  TangentFrame f;
  f.e1 = planar ? Eigen::Vector3d(-normal.y(), normal.x(), 0.0) : normal.unitOrthogonal();
  f.e2 = normal.cross(f.e1);
  return f;
}

}  // namespace impactbench::adapters
