#pragma once
// How an engine (Moreau–Jean, event-driven, Box2D, Bullet) is asked to run a scenario and what
// it hands back, in one layout, so that the CSV writers, the metrics, `run`, `compare` and
// `suite` treat every engine alike.
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "lib/output/trajectory.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::engines {

/// Settings of one run, defaults already resolved from the scenario.
struct RunOptions {
  std::string engine;
  double dt = 0.0;         ///< step [s] (time-stepping engines)
  double tolerance = 0.0;  ///< event location / integration tolerance (event-driven)
  std::string solver;      ///< one-step solver name; empty = the engine's default
  double duration = 0.0;   ///< simulated time [s]
  /// Engine-specific settings as key=value (e.g. velocity_iterations=50 for box2d); an engine
  /// rejects unknown keys with an error naming the valid ones.
  std::map<std::string, std::string> settings;
};

/// One contact at the end of one step, as the engine reports it; the per-step physical-accuracy
/// criteria (Signorini, friction cone, maximum dissipation) are computed from these.
struct ContactSample {
  std::string name;
  double gap = 0.0;                                      ///< [m], negative = penetration
  double impulse_n = 0.0;                                ///< normal impulse of the step [N·s]
  Eigen::Vector2d impulse_t = Eigen::Vector2d::Zero();   ///< tangential impulse (planar: x only)
  double velocity_n = 0.0;                               ///< post-step normal relative velocity
  Eigen::Vector2d velocity_t = Eigen::Vector2d::Zero();  ///< post-step tangential velocity
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

struct RunResult {
  std::string engine;
  output::Trajectory trajectory;
  std::vector<output::EventRecord> events;
  std::vector<StepRecord> steps;
  std::vector<std::pair<std::string, std::string>> settings;  ///< printed in the run summary
  std::vector<std::pair<std::string, std::string>> summary;   ///< engine-specific run summary
  /// Per body: how far above the exact contact height the engine lets it rest [m] (Box2D's
  /// polygon skin); metrics of heights subtract it so each engine is measured from its own rest.
  std::vector<double> rest_offsets;
  double cpu_seconds = 0.0;

  /// Appends a sample; throws std::runtime_error naming the time and the first offending
  /// coordinate when q or v is not finite or the energy is infinite (NaN energy means "not
  /// computed"), so that a run whose state blew up fails instead of writing NaN rows.
  void add_sample(double t, Eigen::VectorXd q, Eigen::VectorXd v, double energy);
};

/// An engine: runs `scenario` with `options`; throws (std::exception) on failure.
using EngineFunction = std::function<RunResult(const scenario::Scenario&, const RunOptions&)>;

}  // namespace impactbench::engines
