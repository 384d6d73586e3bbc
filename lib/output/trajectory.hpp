#pragma once
// An engine's output in memory: samples (t, q, v, energy) with the column names of q and v,
// and the discrete events (impacts, lift-offs, stick/slip transitions) in time order.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace impactbench::output {

struct TrajectorySample {
  double t = 0.0;       ///< [s]
  Eigen::VectorXd q;    ///< positions, in the order of Trajectory::position_names
  Eigen::VectorXd v;    ///< velocities, in the order of Trajectory::velocity_names
  double energy = 0.0;  ///< kinetic + potential [J]
};

struct Trajectory {
  std::vector<std::string> position_names;  ///< e.g. ball.x, ball.y, ball.theta
  std::vector<std::string> velocity_names;  ///< e.g. ball.vx, ball.vy, ball.omega
  std::vector<TrajectorySample> samples;
};

struct EventRecord {
  double t = 0.0;          ///< [s]
  std::string contact;     ///< e.g. "ball-ground", "C_L"
  std::string kind;        ///< "impact", "liftoff", "stick", "slip", ...
  std::string from_mode;   ///< "open", "slip", "stick" before the event
  std::string to_mode;     ///< and after it
  double impulse_n = 0.0;  ///< normal impulse [N s] (0 for events without impact)
  double impulse_t = 0.0;  ///< tangential impulse [N s]: signed planar, magnitude spatial
};

}  // namespace impactbench::output
