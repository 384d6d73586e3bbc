#pragma once
// The initial state of a simulation started from a recorded toss, in the scenarios' convention
// (world-frame angular velocity), either one sample's or a ballistic fit of the samples before
// the first contact; and the `cube_toss` scenario's parameters that set it.
#include <cstddef>
#include <string>

#include "lib/scenario/scenario.hpp"
#include "lib/validation/toss.hpp"

namespace impactbench::validation {

struct InitialState {
  double t = 0.0;  ///< time of the state in the toss's clock [s]
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< WORLD frame [rad/s]
};

/// The cube and the board as the contact detection below sees them.
struct CubeGeometry {
  double side = 0.1048;           ///< edge length [m]
  double board_offset = 0.0;      ///< height of the board's surface [m]
  double contact_margin = 0.005;  ///< a corner this close to the board counts as touching [m]
};

/// Height of the cube's lowest corner: z − side/2 (|R₂₀| + |R₂₁| + |R₂₂|).
double lowest_corner_height(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                            double side);

/// Index of the first sample whose lowest corner is within contact_margin of the board;
/// samples.size() when none is.
std::size_t first_contact_index(const Toss& toss, const CubeGeometry& cube);

/// Sample k as it is, angular velocity turned into the world frame (R(q) ω_body). Throws
/// std::out_of_range for k past the end.
InitialState sample_state(const Toss& toss, std::size_t k);

/// Least-squares fit of the free flight before the first contact, at the time of sample 0:
/// positions p₀ + v₀ τ − ½ g τ² e_z, orientations exp(a + ω τ) q_ref (rotation vectors relative
/// to sample 0; constant world ω, exact for a torque-free body with isotropic inertia). Throws
/// std::runtime_error when fewer than 3 samples precede the first contact.
InitialState fitted_state(const Toss& toss, const CubeGeometry& cube, double gravity);

/// The cube_toss scenario's parameters x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy, wz.
scenario::ParameterOverrides state_parameters(const InitialState& state);
/// Whether `name` is one of those: a parameter that comes from each toss, never from the user.
bool is_state_parameter(const std::string& name);

}  // namespace impactbench::validation
