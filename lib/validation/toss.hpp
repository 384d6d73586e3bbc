#pragma once
// A recorded toss of a rigid body (scenarios/data/cube_toss): poses and velocities sampled in
// time, as the data give them. Angular velocity is in the BODY frame there; scenarios and
// engines use the world frame (toss_state.hpp converts).
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace impactbench::validation {

struct TossSample {
  double t = 0.0;                                                   ///< [s]
  Eigen::Vector3d position = Eigen::Vector3d::Zero();               ///< centre, board frame [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body → board
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();               ///< board frame [m/s]
  Eigen::Vector3d angular_velocity_body = Eigen::Vector3d::Zero();  ///< body frame [rad/s]

  /// R(q) ω_body: the angular velocity in the board (world) frame.
  Eigen::Vector3d angular_velocity_world() const { return orientation * angular_velocity_body; }
};

struct Toss {
  std::string name;  ///< the file's stem, e.g. toss_017
  std::vector<TossSample> samples;
};

}  // namespace impactbench::validation
