#pragma once
// Trajectory column names of free rigid bodies in the design's order, for systems and
// reference engines built from BodySpecs: per body planar x, y, theta (velocities vx, vy,
// omega); spatial x, y, z, qw, qx, qy, qz (velocities vx, vy, vz, wx, wy, wz).
#include <string>
#include <vector>

#include "lib/model/body_spec.hpp"

namespace impactbench::output {

std::vector<std::string> rigid_body_position_names(const std::vector<model::BodySpec>& bodies,
                                                   bool spatial);
std::vector<std::string> rigid_body_velocity_names(const std::vector<model::BodySpec>& bodies,
                                                   bool spatial);

}  // namespace impactbench::output
