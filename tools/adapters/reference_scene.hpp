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

struct ReferenceScene {
  bool planar = true;  ///< planar: y up, (x, y, θ); spatial: z up, position + quaternion
  std::vector<model::BodySpec> bodies;
  std::vector<model::StaticPlaneSpec> planes;
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

/// Thrown when a scene cannot be represented by an engine (e.g. Box2D and a spatial scenario).
struct UnsupportedScene : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace impactbench::adapters
