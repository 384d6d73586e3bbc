#pragma once
// Trajectory errors of positions and of orientations, apart and each in its unit: positions
// as the Euclidean distance [m], orientations as the rotation distance, the angle of
// R_a R_bᵀ [rad], so that q and −q (one rotation, the quaternion double cover) and θ and
// θ + 2π are at distance 0.
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lib/metrics/trajectory_error.hpp"

namespace impactbench::metrics {

/// Where the coordinates of a state are: positions, planar angles, and the first index (qw)
/// of each unit quaternion (qw, qx, qy, qz).
struct PoseLayout {
  std::vector<int> positions;
  std::vector<int> angles;
  std::vector<int> quaternions;
};

/// The layout of the trajectory columns `<body>.x|y|z` (positions), `<body>.theta|phi`
/// (planar angles) and `<body>.qw, qx, qy, qz` (orientations). Throws std::invalid_argument on
/// a column that is none of these or a quaternion that is not four consecutive columns.
PoseLayout pose_layout(const std::vector<std::string>& position_names);

/// The angle of the rotation that takes b to a, in [0, π] [rad].
double rotation_distance(double theta_a, double theta_b);
double rotation_distance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

struct PoseTrajectoryError {
  TrajectoryError position;     ///< ‖p − p_ref‖ over every position coordinate [m; L1: m·s]
  TrajectoryError orientation;  ///< (Σ_bodies angle(R R_refᵀ)²)^½ [rad; L1: rad·s]
};

/// Both errors of `trajectory` against `reference` (trajectory_error's sampling and rules).
/// The reference's quaternions are made sign-continuous before they are interpolated.
PoseTrajectoryError pose_trajectory_error(const Signal& trajectory, const Signal& reference,
                                          const PoseLayout& layout);

}  // namespace impactbench::metrics
