#pragma once
// The coordinates in which gains are reported, the same for the gains CSV and the Python module:
// the model's own state for planar systems and the plank–box; for spatial bodies the tangent
// coordinates (HybridModel::tangent_basis): per body δx δy δz and the world rotation vector
// δθx δθy δθz, then the velocities, then μ and e when they are states.
#include <string>
#include <vector>

#include "lib/sensitivity/conewise_jump_gain.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"

namespace impactbench::sensitivity {

/// One order's Gz and Gv in the reported coordinates (Gz maps the pre-event perturbation of
/// `event`, Gv the input perturbation, both to the post-event one that order reaches).
ComposedGain reported_gain(const HybridModel& model, const ConewiseJumpGain& event,
                           ComposedGain gain);

/// The end-point matrices in the reported coordinates.
EndPointSensitivity reported_end_point(const TrajectorySensitivity& sensitivity,
                                       EndPointSensitivity end_point);

/// The names of the reported coordinates: the position names with each body's quaternion
/// `b.qw b.qx b.qy b.qz` replaced by its rotation vector `b.rx b.ry b.rz` when the model has
/// tangent coordinates, then the velocity names, then `friction` and `restitution` when
/// `parameters` is 2.
std::vector<std::string> reported_state_names(const HybridModel& model,
                                              const std::vector<std::string>& position_names,
                                              const std::vector<std::string>& velocity_names,
                                              int parameters);

}  // namespace impactbench::sensitivity
