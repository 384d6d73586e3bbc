#pragma once
// `impactbench compare`: one scenario, several engines, one table and one picture. Runs each
// engine, measures it against the scenario's closed forms and against a reference trajectory
// (the event-driven run where the scenario has one, else Moreau–Jean at a tenth of the step),
// and writes metrics.csv, each engine's trajectory/events/error CSVs and the plots into a
// directory.
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lib/engines/run_result.hpp"
#include "tools/compare/analytic_errors.hpp"

namespace impactbench::compare {

struct CompareOptions {
  std::vector<std::string> engines;  ///< empty: every available engine the scenario lists
  /// Time step [s] of the engines that have one (the event engine has none); unset: scenario's.
  std::optional<double> dt;
  std::optional<double> duration;  ///< unset: the scenario's
  /// Tolerance (--tol) of the engines that have one; unset: the scenario's.
  std::optional<double> tolerance;
  /// Contact solver (--solver) of the engines that have a choice; unset: each engine's.
  std::optional<std::string> solver;
  std::filesystem::path out;  ///< output directory (created if missing)
  /// The settings sets each engine runs with, in order (default: its defaults only). With
  /// kExpert an engine that has an expert set runs it, labelled `ENGINE (expert)`; one without
  /// runs its defaults, once when kDefault is also listed (the suite lists both).
  std::vector<engines::SettingsSet> settings_sets = {engines::SettingsSet::kDefault};
  /// Engine name → settings (as `--option ENGINE.key=value`) for that engine's runs.
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> settings;
  std::filesystem::path python;     ///< interpreter with matplotlib; empty = no plots
  std::filesystem::path tools_dir;  ///< where plot_compare.py lives
  /// Called with the progress of every run (simulated time); may throw ProcessInterrupted
  /// (run_process.hpp) to end the comparison, e.g. on a Ctrl-C seen by a Python caller.
  std::function<void(double t)> progress;
};

struct EngineRow {
  std::string engine;   ///< its label: the engine's name, `ENGINE (expert)` at its expert set
  NamedValues values;   ///< metric name → value, in the column order of metrics.csv
  std::string note;     ///< why a figure is empty (unconverged_steps of Box2D, Bullet, ODE)
  std::string failure;  ///< why the engine's run failed (then `values` is empty), else empty
  std::string asked;    ///< what it was asked to do: step, tolerance, solver, iterations
};

struct CompareReport {
  std::string reference;  ///< engine and setting of the reference trajectory, or "none"
  std::vector<EngineRow> rows;
  std::vector<std::string> plots;  ///< PNG files written
  /// True when at least one engine's run failed (its row holds the reason).
  bool any_failed() const;
  /// The metric names of the rows, in order (every row that ran has the same).
  std::vector<std::string> metric_names() const;
  /// The row labelled `engine`; throws std::out_of_range when there is none.
  const EngineRow& row(const std::string& engine) const;
};

/// The metrics of one run against a reference run (may be null) and the scenario.
NamedValues run_metrics(const scenario::Scenario& scenario, const engines::RunResult& run,
                        const engines::RunResult* reference);

/// `engines`, or every available engine the scenario lists when it is empty.
std::vector<std::string> compared_engines(const scenario::Scenario& scenario,
                                          const std::vector<std::string>& engines);

/// The runs compared: each engine (options.engines, or every available one the scenario lists)
/// at each of options.settings_sets it has, with the settings of each run, through
/// engines::resolve_run_options. Throws std::invalid_argument
/// for a setting an engine refuses, for settings of an engine not compared, and for --dt when
/// no compared engine has a time step.
std::vector<engines::RunOptions> resolve_compare_runs(const scenario::Scenario& scenario,
                                                      const CompareOptions& options);

/// A run's label in tables: the engine's name, with " (expert)" when its expert set is in force.
std::string run_label(const engines::RunOptions& options);

/// "key=value (source); ..." for the settings column of metrics.csv: duration, then every
/// setting in force of the run (of a failed run: the settings it was asked to run with).
std::string settings_text(const engines::RunOptions& options, const engines::SettingList& settings);

/// Runs the comparison and writes its files. An engine whose run fails (it throws) gets its
/// row with the reason and no figures, and the others are measured and written as usual;
/// throws on unwritable output, a failed plot, or an interrupt.
CompareReport run_compare(const scenario::Scenario& scenario, const CompareOptions& options);

/// The table as printed by the CLI (fixed-width columns).
std::string format_report(const CompareReport& report);

}  // namespace impactbench::compare
