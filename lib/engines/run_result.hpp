#pragma once
// What every engine (Moreau–Jean, event-driven, Box2D, Bullet) hands back from a run, in one
// layout, so that the CSV writers, the metrics and the compare tool treat them alike.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace impactbench::engines {

/// One contact at the end of one step, as the engine reports it; the per-step physical-accuracy
/// criteria (Signorini, friction cone, maximum dissipation) are computed from these.
struct ContactSample {
  std::string name;
  double gap = 0.0;                                      ///< [m], negative = penetration
  double impulse_n = 0.0;                                ///< normal impulse over the step [N·s]
  Eigen::Vector2d impulse_t = Eigen::Vector2d::Zero();   ///< tangential impulse (planar: x only)
  double velocity_n = 0.0;                               ///< post-step normal relative velocity
  Eigen::Vector2d velocity_t = Eigen::Vector2d::Zero();  ///< post-step tangential relative velocity
  double friction = 0.0;                                 ///< μ used for this contact
};

/// Statistics of one time step (time-stepping engines) or one flow segment (event-driven).
struct StepRecord {
  double t = 0.0;  ///< end time of the step
  int active_contacts = 0;
  int iterations = 0;
  double residual = 0.0;
  double solve_seconds = 0.0;
  bool converged = true;
  std::vector<ContactSample> contacts;
};

/// A row of the events CSV: t, contact, kind, from_mode, to_mode, impulse_n, impulse_t.
struct EventRecord {
  double t = 0.0;
  std::string contact;
  std::string kind;  ///< impact, liftoff, slip_to_stick, stick_to_slip, rest, ...
  std::string from_mode;
  std::string to_mode;
  double impulse_n = 0.0;
  double impulse_t = 0.0;
};

struct RunResult {
  std::string engine;
  std::vector<std::string> position_names;  ///< trajectory CSV columns for q
  std::vector<std::string> velocity_names;  ///< trajectory CSV columns for v
  std::vector<double> times;
  std::vector<Eigen::VectorXd> positions;
  std::vector<Eigen::VectorXd> velocities;
  std::vector<double> energy;
  std::vector<EventRecord> events;
  std::vector<StepRecord> steps;
  std::vector<std::pair<std::string, std::string>> settings;  ///< printed in the run summary
  /// Per body: how far above the exact contact height the engine lets it rest [m] (Box2D's
  /// polygon skin); metrics of heights subtract it so each engine is measured from its own rest.
  std::vector<double> rest_offsets;
  double cpu_seconds = 0.0;
  bool succeeded = true;
  std::string failure;  ///< why not, when !succeeded

  void add_sample(double t, Eigen::VectorXd q, Eigen::VectorXd v, double e) {
    times.push_back(t);
    positions.push_back(std::move(q));
    velocities.push_back(std::move(v));
    energy.push_back(e);
  }
};

}  // namespace impactbench::engines
