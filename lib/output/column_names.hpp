#pragma once
// Trajectory column names of free rigid bodies in the design's order, for every system and
// reference engine built from bodies: per body planar x, y, theta (velocities vx, vy, omega);
// spatial x, y, z, qw, qx, qy, qz (velocities vx, vy, vz, wx, wy, wz). The one place these
// names are spelled.
#include <string>
#include <vector>

#include "lib/model/body_spec.hpp"

namespace impactbench::output {

std::vector<std::string> rigid_body_position_names(const std::vector<std::string>& body_names,
                                                   bool spatial);
std::vector<std::string> rigid_body_velocity_names(const std::vector<std::string>& body_names,
                                                   bool spatial);

/// The same, from the bodies' specs.
std::vector<std::string> rigid_body_position_names(const std::vector<model::BodySpec>& bodies,
                                                   bool spatial);
std::vector<std::string> rigid_body_velocity_names(const std::vector<model::BodySpec>& bodies,
                                                   bool spatial);

}  // namespace impactbench::output
