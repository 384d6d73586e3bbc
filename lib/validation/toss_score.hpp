#pragma once
// Scoring a simulated toss against the recording, as Acosta, Yang & Posa (RA-L 2022) scored
// simulators on these data: errors averaged over the recorded samples from the start sample to
// the end, plus the rest pose (the last sample) and the time of the first contact.
#include <cstddef>
#include <string>
#include <vector>

#include "lib/output/trajectory.hpp"
#include "lib/validation/toss.hpp"
#include "lib/validation/toss_state.hpp"

namespace impactbench::validation {

/// One simulated state in the data's convention but with WORLD-frame angular velocity.
struct SimulatedPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< world frame
};

struct TossScore {
  double position = 0.0;          ///< mean ‖Δp‖ / side [1]
  double rotation = 0.0;          ///< mean angle of R_sim R_dataᵀ [rad]
  double velocity = 0.0;          ///< mean ‖Δv‖ [m/s]
  double angular_velocity = 0.0;  ///< mean ‖Δω‖, world frame [rad/s]
  double rest_position = 0.0;     ///< ‖Δp‖ at the last sample [m]
  double rest_rotation = 0.0;     ///< angle of R_sim R_dataᵀ at the last sample [rad]
  /// |t_sim − t_data| of the first sample whose lowest corner is within contact_margin of the
  /// board; a side that never gets there counts the toss's last sample time [s].
  double first_contact_time = 0.0;
};

/// The errors at one recorded sample, the quantities position and rotation average.
struct SampleError {
  double time = 0.0;      ///< since the run's first sample [s]
  double position = 0.0;  ///< ‖Δp‖ / side [1]
  double rotation = 0.0;  ///< angle of R_sim R_dataᵀ [rad]
};

/// The metrics' names, in the order of TossScore's fields (CSV columns and table rows).
const std::vector<std::string>& score_names();
/// The fields of `score` in score_names()'s order.
std::vector<double> score_values(const TossScore& score);

/// Scores `simulated`, the states at the data's sample times from `start` on (one per sample,
/// simulated[i] at samples[start + i]). Throws std::invalid_argument on a size mismatch.
TossScore score_toss(const Toss& data, std::size_t start,
                     const std::vector<SimulatedPose>& simulated, const CubeGeometry& cube);

/// The position and rotation errors of `simulated` at each of its samples (as score_toss takes
/// them), for plots against time. Throws std::invalid_argument on a size mismatch.
std::vector<SampleError> sample_errors(const Toss& data, std::size_t start,
                                       const std::vector<SimulatedPose>& simulated,
                                       const CubeGeometry& cube);

/// The states of body `body` of an engine's trajectory (columns <body>.x … <body>.wz) at the
/// data's times from `start` on, the simulation's clock starting at samples[start].t: positions
/// and velocities interpolated linearly, quaternions made sign-continuous, interpolated and
/// normalised. Throws std::invalid_argument when a column is missing or nothing was sampled.
std::vector<SimulatedPose> poses_at_samples(const output::Trajectory& trajectory,
                                            const std::string& body, const Toss& data,
                                            std::size_t start);

}  // namespace impactbench::validation
