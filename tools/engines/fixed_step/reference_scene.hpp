#pragma once
// A scenario as the reference engines see it: rigid bodies, static half-spaces, one material,
// gravity and force inputs. Built from the same scenario definitions as our own systems.
#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "lib/model/body_spec.hpp"

namespace impactbench::adapters {

/// A planar body turning about the world's z axis through `anchor` (a revolute joint to the
/// world), loaded by a torsional spring and damper: torque −stiffness·φ − damping·φ̇, φ the
/// body's angle (0 as placed at rest angle 0). Its trajectory columns are `<body>.phi` and
/// `<body>.omega` alone.
struct HingeSpec {
  int body = 0;  ///< index into ReferenceScene::bodies
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
  double stiffness = 0.0;  ///< [N·m/rad]
  double damping = 0.0;    ///< [N·m·s/rad]
};

struct ReferenceScene {
  bool planar = true;  ///< planar: y up, (x, y, θ); spatial: z up, position + quaternion
  std::vector<model::BodySpec> bodies;
  std::vector<model::StaticPlaneSpec> planes;
  std::vector<HingeSpec> hinges;  ///< planar only; bodies not named here are free
  model::Material material;
  double gravity = 9.81;  ///< [m/s²], along −y (planar) or −z (spatial)
  std::vector<model::ForceInputSpec> inputs;
  std::function<Eigen::VectorXd(double)> input;  ///< u(t), one entry per input; may be empty
  double duration = 1.0;                         ///< [s]
  double dt = 1.0 / 240;                         ///< [s]
  /// Energy of a state in our coordinate layout, so every engine's energy column is computed by
  /// the same code (our system's energy()).
  std::function<double(const Eigen::VectorXd& q, const Eigen::VectorXd& v)> energy;
};

/// The force u_j(t)·direction_j of every input channel at time t, with the index of the body
/// (in scene.bodies) it pushes; empty without inputs. Both engines apply these at the centres.
std::vector<std::pair<int, Eigen::Vector3d>> input_forces(const ReferenceScene& scene, double t);

/// The hinge holding body `body`, or nullptr for a free body.
const HingeSpec* hinge_of(const ReferenceScene& scene, int body);

/// The spring–damper torque about z of every hinge, −k φ − b φ̇, for engines without native
/// joint stiffness; `angle` and `rate` give a body's φ and φ̇.
double hinge_torque(const HingeSpec& hinge, double angle, double rate);

/// Thrown when a scene cannot be represented by an engine (e.g. Box2D and a spatial scenario).
struct UnsupportedScene : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace impactbench::adapters
