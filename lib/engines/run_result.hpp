#pragma once
// How an engine (Moreau–Jean, event-driven, Box2D, Bullet) is asked to run a scenario and what
// it hands back, in one layout, so that the CSV writers, the metrics, `run`, `compare` and
// `suite` treat every engine alike.
#include <any>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/run_timer.hpp"
#include "lib/engines/settings/setting_fields.hpp"
#include "lib/engines/settings/settings_set.hpp"
#include "lib/output/trajectory.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::engines {

/// What a run keeps of its output and where its samples go. The library's default keeps every
/// sample and step record in memory (RunResult::trajectory, RunResult::steps); `impactbench
/// run` streams sampled states to its CSV through `sample_sink` and keeps neither, so a run's
/// memory does not grow with its length.
struct RecordingOptions {
  /// Simulated time between kept samples [s]; 0 = every state the engine offers (each step, the
  /// event engine's samples). The first and the last state are always kept, and so is a state
  /// at the same time as the last one kept (before and after an event instant).
  double sample_interval = 0.0;
  /// When > 0, the interval is widened if needed so that a run of `duration` keeps about at
  /// most this many numbers (rows × columns of the trajectory CSV).
  double max_values = 0.0;
  double duration = 0.0;     ///< [s], for max_values
  bool keep_samples = true;  ///< in RunResult::trajectory.samples
  bool keep_steps = true;    ///< in RunResult::steps (their totals are always counted)
  /// A timing run: the engine steps with nothing of ours between its steps (no state, contact,
  /// event or step record is read), so that its CPU time per step is that of a bare loop, with
  /// caches as the engine left them. The result holds the initial and the final state, the step
  /// count and the timing. The fixed-step engines and Moreau–Jean support it; the others refuse.
  bool timing_only = false;
  /// Receives every kept sample in time order, with the trajectory's column names.
  std::function<void(const output::Trajectory& names, const output::TrajectorySample&)> sample_sink;
  /// Called with the time of every state offered (progress of a long run).
  std::function<void(double t)> progress;
};

/// Most samples or step records a run keeps in memory; beyond it the run fails with a message
/// that says how to stream instead.
inline constexpr long kMaxKeptRecords = 10'000'000;

/// Settings of one run, every one resolved (engines::resolve_run_options, run_settings.hpp):
/// the engine runs with `engine_options`, its options struct, which its schema parsed once from
/// what was given; `settings` is the same in force as text, for reports.
struct RunOptions {
  std::string engine;
  /// The settings set asked for (`--settings`); an engine without an expert set runs its
  /// defaults under kExpert (applies_settings_set in tools/engines/registry/run_settings.hpp).
  SettingsSet settings_set = SettingsSet::kDefault;
  double duration = 0.0;  ///< simulated time [s]
  SettingSource duration_source = SettingSource::kScenario;
  /// Every key of the engine with its value in force and source, as reports print them.
  SettingList settings;
  std::any engine_options;  ///< the engine's options struct (an O of its SettingsSchema<O>)
  RecordingOptions recording;
};

/// The options struct O that resolving the settings of `options.engine` made; throws
/// std::invalid_argument when `options` holds none of that type (it was not resolved for it).
template <typename O>
const O& engine_options_of(const RunOptions& options) {
  const O* typed = std::any_cast<O>(&options.engine_options);
  if (typed == nullptr)
    throw std::invalid_argument(options.engine +
                                ": the run's settings were not resolved for this engine");
  return *typed;
}

/// One contact at the end of one step, as the engine reports it; the per-step physical-accuracy
/// criteria (Signorini, friction cone, maximum dissipation) are computed from these.
struct ContactSample {
  std::string name;
  double gap = 0.0;                                     ///< [m], negative = penetration
  double impulse_n = 0.0;                               ///< normal impulse of the step [N·s]
  Eigen::Vector2d impulse_t = Eigen::Vector2d::Zero();  ///< tangential impulse (planar: x only)
  double velocity_n = 0.0;                              ///< post-step normal relative velocity
  double velocity_n_before = 0.0;  ///< pre-step normal relative velocity ζ_n⁻ (< 0: approaching)
  Eigen::Vector2d velocity_t = Eigen::Vector2d::Zero();  ///< post-step tangential velocity
  double friction = 0.0;                                 ///< μ used for this contact
  double restitution = 0.0;  ///< e of Newton's law for this contact (ζ_n⁺ = −e ζ_n⁻ at an impact)
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

/// A run's output. Engines (and adapters) record through four calls: set `recording` from
/// RunOptions::recording before the first state, add_sample for every state (the initial one
/// and the end of every step), add_step for every step, finish_recording at the end.
struct RunResult {
  std::string engine;
  RecordingOptions recording;
  output::Trajectory trajectory;  ///< names always; samples when recording.keep_samples
  std::vector<output::EventRecord> events;
  std::vector<StepRecord> steps;  ///< when recording.keep_steps
  SettingList settings;  ///< every setting in force with its source, printed in the run summary
  std::vector<std::pair<std::string, std::string>> summary;  ///< engine-specific run summary

  // What the run cost and how well it solved its contact problems: the same figures for every
  // engine (RunTimer splits the CPU time).
  double engine_cpu_seconds = 0.0;  ///< process CPU time of the engine's stepping alone [s]
  double record_cpu_seconds =
      0.0;                    ///< process CPU time of our recording (samples, contacts, events) [s]
  double wall_seconds = 0.0;  ///< wall-clock time of stepping and recording together [s]
  long step_count = 0;        ///< time steps taken (event-driven: its flow integrator's steps)
  /// Steps whose contact problem was not solved to tolerance; empty for an engine that has no
  /// tolerance to reach, with `unconverged_note` saying why.
  std::optional<long> unconverged_steps;
  std::string unconverged_note;
  /// A known defect of the engine itself that showed in this run, counted, with its source
  /// (e.g. MuJoCo 2.2.2's phantom box–box contacts); empty when none did.
  std::string defect_note;
  /// Largest residual of the steps not solved to tolerance (0 when all were).
  double worst_unconverged_residual = 0.0;
  double mean_contacts = 0.0;  ///< contacts in the contact problem, averaged over time
  /// Deepest penetration over every contact the engine's geometry finds in every recorded
  /// state, whether or not the contact entered the contact problem [m].
  double max_penetration = 0.0;

  // The samples kept (in memory or through the sink), counted whether or not they are stored.
  long sample_count = 0;
  double first_energy = 0.0;  ///< energy of the first kept sample [J]
  double last_energy = 0.0;   ///< and of the last

  void set_timing(const RunTimer& timer) {
    engine_cpu_seconds = timer.engine_cpu_seconds();
    record_cpu_seconds = timer.record_cpu_seconds();
    wall_seconds = timer.wall_seconds();
  }
  /// step_count, unconverged_steps (when the engine has a tolerance) and mean_contacts from the
  /// steps added, for the time-stepping engines.
  void count_steps(bool has_tolerance);

  /// Offers a state. Throws std::runtime_error naming the time and the first offending
  /// coordinate when q or v is not finite or the energy is infinite (NaN energy means "not
  /// computed"), so that a run whose state blew up fails instead of writing NaN rows. Keeps it
  /// when the sampling says so (RecordingOptions::sample_interval); else holds it until the
  /// next, so that finish_recording can keep the last state.
  void add_sample(double t, Eigen::VectorXd q, Eigen::VectorXd v, double energy);
  /// Counts a step (totals for count_steps) and keeps it when recording.keep_steps.
  void add_step(StepRecord step);
  /// Keeps the last state offered if the sampling skipped it. Call once, after the last state.
  void finish_recording();

 private:
  void keep(output::TrajectorySample sample);

  double effective_interval_ = -1.0;  // resolved at the first sample; < 0 = not yet
  double next_sample_time_ = 0.0;
  double last_kept_time_ = 0.0;
  std::optional<output::TrajectorySample> pending_;
  long steps_added_ = 0, unconverged_added_ = 0, contacts_added_ = 0;
};

/// An engine: runs `scenario` with `options`; throws (std::exception) on failure.
using EngineFunction = std::function<RunResult(const scenario::Scenario&, const RunOptions&)>;

}  // namespace impactbench::engines
