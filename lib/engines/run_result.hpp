#pragma once
// How an engine (Moreau–Jean, event-driven, Box2D, Bullet) is asked to run a scenario and what
// it hands back, in one layout, so that the CSV writers, the metrics, `run`, `compare` and
// `suite` treat every engine alike.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/run_timer.hpp"
#include "lib/engines/settings/setting_fields.hpp"
#include "lib/output/trajectory.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::engines {

/// Settings of one run, every one resolved (engines::resolve_run_options, run_settings.hpp):
/// the engine reads its keys from `settings` and nothing else.
struct RunOptions {
  std::string engine;
  double duration = 0.0;  ///< simulated time [s]
  SettingSource duration_source = SettingSource::kScenario;
  /// Every key of the engine with its value in force and source; an engine rejects unknown keys.
  SettingList settings;
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
  SettingList settings;  ///< every setting in force with its source, printed in the run summary
  std::vector<std::pair<std::string, std::string>> summary;  ///< engine-specific run summary
  /// Per body: how far above the exact contact height the engine lets it rest [m] (Box2D's
  /// polygon skin); metrics of heights subtract it so each engine is measured from its own rest.
  std::vector<double> rest_offsets;

  // What the run cost and how well it solved its contact problems: the same figures for every
  // engine (RunTimer splits the CPU time).
  double engine_cpu_seconds = 0.0;  ///< process CPU time of the engine's stepping alone [s]
  double record_cpu_seconds =
      0.0;                    ///< process CPU time of our recording (samples, contacts, events) [s]
  double wall_seconds = 0.0;  ///< wall-clock time of stepping and recording together [s]
  long step_count = 0;        ///< time steps taken (event-driven: CVODE's steps)
  /// Steps whose contact problem was not solved to tolerance; empty for an engine that has no
  /// tolerance to reach, with `unconverged_note` saying why.
  std::optional<long> unconverged_steps;
  std::string unconverged_note;
  double mean_contacts = 0.0;  ///< contacts in the contact problem, averaged over time
  /// Deepest penetration over every contact the engine's geometry finds in every recorded
  /// state, whether or not the contact entered the contact problem [m].
  double max_penetration = 0.0;

  void set_timing(const RunTimer& timer) {
    engine_cpu_seconds = timer.engine_cpu_seconds();
    record_cpu_seconds = timer.record_cpu_seconds();
    wall_seconds = timer.wall_seconds();
  }
  /// step_count, unconverged_steps (when the engine has a tolerance) and mean_contacts from
  /// `steps`, for the time-stepping engines.
  void count_steps(bool has_tolerance) {
    step_count = static_cast<long>(steps.size());
    long unconverged = 0, contacts = 0;
    for (const StepRecord& step : steps) {
      unconverged += step.converged ? 0 : 1;
      contacts += step.active_contacts;
    }
    if (has_tolerance) unconverged_steps = unconverged;
    mean_contacts = steps.empty() ? 0.0 : static_cast<double>(contacts) / step_count;
  }

  /// Appends a sample; throws std::runtime_error naming the time and the first offending
  /// coordinate when q or v is not finite or the energy is infinite (NaN energy means "not
  /// computed"), so that a run whose state blew up fails instead of writing NaN rows.
  void add_sample(double t, Eigen::VectorXd q, Eigen::VectorXd v, double energy);
};

/// An engine: runs `scenario` with `options`; throws (std::exception) on failure.
using EngineFunction = std::function<RunResult(const scenario::Scenario&, const RunOptions&)>;

}  // namespace impactbench::engines
