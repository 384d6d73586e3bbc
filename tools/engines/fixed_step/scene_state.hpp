#pragma once
// A reference engine's bodies as our trajectory's columns: every adapter reads its engine's
// body poses and velocities into BodyState and turns them into (q, v) here, so the column
// layout (lib/output/column_names.hpp; a hinged body contributes phi and omega alone) is written
// once.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "lib/engines/run_result.hpp"
#include "tools/engines/fixed_step/reference_scene.hpp"

namespace impactbench::adapters {

/// One body as an engine reports it, world frame (planar scenes: the x–y plane).
struct BodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  /// A planar body's angle as the engine tracks it, unwrapped (Box2D, MuJoCo's hinge); unset:
  /// read from the orientation, in (−π, π].
  std::optional<double> angle;
};

std::vector<std::string> scene_position_names(const ReferenceScene& scene);
std::vector<std::string> scene_velocity_names(const ReferenceScene& scene);

/// The rotation about z of a planar body's orientation [rad].
double planar_angle(const Eigen::Quaterniond& orientation);

struct SceneCoordinates {
  Eigen::VectorXd q;
  Eigen::VectorXd v;
};

/// Velocity of body `body`'s material point at world point p (body < 0: a boundary, at rest).
Eigen::Vector3d point_velocity(const std::vector<BodyState>& states, int body,
                               const Eigen::Vector3d& p);

/// Where the material point of body `body` at p in state `before` is in state `after`
/// (body < 0: p).
Eigen::Vector3d moved_point(const std::vector<BodyState>& before,
                            const std::vector<BodyState>& after, int body,
                            const Eigen::Vector3d& p);

/// (q, v) in the layout of the names above; `bodies` in the order of scene.bodies.
SceneCoordinates scene_coordinates(const ReferenceScene& scene,
                                   const std::vector<BodyState>& bodies);

/// The result of `engine` on the scene before its first sample: its name, the recording
/// options, the scene's column names and a rest offset of 0 for every body (an engine whose
/// shapes carry a skin sets its own).
engines::RunResult scene_result(const std::string& engine, const ReferenceScene& scene,
                                const engines::RecordingOptions& recording);

/// Adds the sample of time t to `result`: the bodies' coordinates and the scene's energy (NaN
/// when the scene has no energy function).
void add_scene_sample(engines::RunResult& result, const ReferenceScene& scene,
                      const std::vector<BodyState>& bodies, double t);

}  // namespace impactbench::adapters
