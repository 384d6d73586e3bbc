#pragma once
// Plain descriptions of rigid bodies, static boundaries and inputs, filled by the scenario
// loader and consumed by our systems and by the Box2D/Bullet adapters alike.
#include <optional>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace impactbench::model {

enum class ShapeKind {
  kDisk,    ///< planar circle, `radius`
  kBox,     ///< planar rectangle, `size` = (width, height)
  kSphere,  ///< spatial ball, `radius`
  kCuboid,  ///< spatial box, `size` = full side lengths (x, y, z)
};

struct BodySpec {
  std::string name;
  ShapeKind shape = ShapeKind::kDisk;
  double radius = 0.0;                             ///< [m]
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  ///< full side lengths [m]
  double mass = 1.0;                               ///< [kg], > 0
  /// Spatial only: principal moments of inertia about the body axes through the centre
  /// [kg m²]; empty: those of a uniform solid of the shape (body_inertia.hpp).
  std::optional<Eigen::Vector3d> inertia;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< centre [m]; planar uses x, y
  double angle = 0.0;                                  ///< planar θ [rad]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< spatial
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();               ///< [m/s]
  Eigen::Vector3d angular_velocity =
      Eigen::Vector3d::Zero();  ///< world frame [rad/s]; planar uses z
};

/// A static half-space boundary: planar a line, spatial a plane, through `point` with outward
/// unit `normal` (bodies live on the side the normal points to).
struct StaticPlaneSpec {
  std::string name = "ground";
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
};

/// Contact material, the same for every pair of a scenario (our engines); the adapters map it
/// through each engine's combine rule.
struct Material {
  double friction = 0.0;     ///< μ ≥ 0
  double restitution = 0.0;  ///< e ∈ [0, 1]
};

/// Input channel k of a rigid-body system: a force of magnitude u_k(t) [N] along the fixed world
/// `direction` at the centre of body `body`.
struct ForceInputSpec {
  std::string body;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};

}  // namespace impactbench::model
