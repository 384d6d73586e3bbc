#include "tools/compare/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "lib/metrics/contact_criteria.hpp"
#include "lib/metrics/energy_drift.hpp"
#include "lib/metrics/pose_error.hpp"
#include "lib/metrics/run_figures.hpp"
#include "lib/metrics/run_signal.hpp"
#include "lib/output/column_names.hpp"
#include "lib/output/number_text.hpp"
#include "lib/output/run_outputs.hpp"
#include "lib/output/table_csv.hpp"
#include "tools/compare/asked_settings.hpp"
#include "tools/compare/run_process.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"

namespace impactbench::compare {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> energies(const engines::RunResult& run) {
  std::vector<double> e;
  for (const auto& sample : run.trajectory.samples) e.push_back(sample.energy);
  return e;
}

std::vector<std::string> available_engines(const scenario::Scenario& s) {
  std::vector<std::string> names;
  for (const auto& info : adapters::engine_registry())
    if (info.run && s.supports_engine(info.name)) names.push_back(info.name);
  return names;
}

bool available(const scenario::Scenario& s, const std::string& engine) {
  const auto* info = adapters::find_engine(engine);
  return info && info->run && s.supports_engine(engine);
}

// Positions [m] and orientations [rad] of a run against the reference, apart.
metrics::PoseTrajectoryError pose_error(const engines::RunResult& run,
                                        const engines::RunResult& reference) {
  return metrics::pose_trajectory_error(metrics::position_signal(run),
                                        metrics::position_signal(reference),
                                        metrics::pose_layout(run.trajectory.position_names));
}

void write_error_csv(const std::filesystem::path& path, const metrics::PoseTrajectoryError& error) {
  output::Table table{{"t", "error", "angle_error"}, {}};
  for (std::size_t i = 0; i < error.position.times.size(); ++i)
    table.rows.push_back(
        {error.position.times[i], error.position.errors[i], error.orientation.errors[i]});
  output::write_table_csv(path, table);
}

std::vector<std::string> plotted_columns(const scenario::Scenario& s) {
  if (s.bodies.empty()) return {};
  if (s.system == scenario::SystemKind::kPlankBox)
    return {"box.x", "box.y", "box.theta", "plank.phi"};
  // The cradle's last ball, the only body elsewhere: its planar x, y, theta or spatial x, y, z.
  auto columns = output::rigid_body_position_names(std::vector<model::BodySpec>{s.bodies.back()},
                                                   s.dimension != scenario::Dimension::kPlanar);
  columns.resize(3);
  return columns;
}

// The smallest step of the runs that have one; none when no run steps.
std::optional<double> finest_step(const std::vector<engines::RunOptions>& runs) {
  std::optional<double> finest;
  for (const engines::RunOptions& run : runs)
    if (const engines::EngineSettings* info = engines::find_engine_settings(run.engine))
      for (const std::string& key : info->dt_keys) {
        const double h = engines::setting_number(run.settings, key);
        if (!finest || h < *finest) finest = h;
      }
  return finest;
}

// The event-driven reference samples at least as finely as the compared runs: interpolated
// linearly at a compared run's times, a reference sampled every Δ is off by up to a·Δ²/8 under
// an acceleration a (6.1e-5 m on the sliding block at the default Δ = 0.01 s, all of
// Moreau–Jean's reported error there); sampled every h, by a·h²/8, below a first-order
// scheme's error at that step.
// `event` (resolved from `request`), or when it samples more coarsely than the finest step of
// `runs`, resolved again with that step as its output interval (source "reference sampling").
engines::RunOptions sampled_as_reference(const scenario::Scenario& s,
                                         engines::SettingsRequest request,
                                         engines::RunOptions event,
                                         const std::vector<engines::RunOptions>& runs) {
  const auto step = finest_step(runs);
  if (!step || engines::setting_number(event.settings, "output_interval") <= *step) return event;
  request.reference_sampling = {{"output_interval", output::number_text(*step)}};
  return engines::resolve_run_options(engine_name::kEvent, s, request);
}

}  // namespace

namespace {

// The metrics of one run, given its error against the reference (null: no reference), which
// run_compare also writes to <engine>_error.csv and so computes once.
NamedValues run_metrics_with(const scenario::Scenario& scenario, const engines::RunResult& run,
                             const metrics::PoseTrajectoryError* error) {
  NamedValues values = metrics::run_figures(run);
  values.emplace_back("events", static_cast<double>(run.events.size()));
  for (auto& named : analytic_errors(scenario, run)) values.push_back(std::move(named));
  if (error) {
    values.emplace_back("l1_error", error->position.l1);
    values.emplace_back("linf_error", error->position.linf);
    values.emplace_back("l1_angle_error", error->orientation.l1);
    values.emplace_back("linf_angle_error", error->orientation.linf);
  } else {
    for (const char* name : {"l1_error", "linf_error", "l1_angle_error", "linf_angle_error"})
      values.emplace_back(name, kNaN);
  }
  const auto criteria = metrics::worst_contact_criteria(run.steps);
  values.emplace_back("max_penetration", run.max_penetration);
  const auto drift = metrics::energy_drift(energies(run));
  values.emplace_back("energy_drift", drift.relative_change);
  values.emplace_back("energy_max_rise", drift.max_rise);
  values.emplace_back("signorini", criteria.signorini);
  values.emplace_back("friction_cone", criteria.friction_cone);
  values.emplace_back("max_dissipation", criteria.max_dissipation);
  values.emplace_back("complementarity", criteria.complementarity);
  return values;
}

}  // namespace

NamedValues run_metrics(const scenario::Scenario& scenario, const engines::RunResult& run,
                        const engines::RunResult* reference) {
  if (!reference || reference == &run) return run_metrics_with(scenario, run, nullptr);
  const auto error = pose_error(run, *reference);
  return run_metrics_with(scenario, run, &error);
}

std::vector<std::string> compared_engines(const scenario::Scenario& s,
                                          const std::vector<std::string>& engines) {
  return engines.empty() ? available_engines(s) : engines;
}

std::vector<engines::RunOptions> resolve_compare_runs(const scenario::Scenario& s,
                                                      const CompareOptions& options) {
  const std::vector<std::string> engine_names = compared_engines(s, options.engines);
  if (engine_names.empty())
    throw std::invalid_argument("compare: no available engine can run scenario '" + s.name + "'");
  for (const auto& [engine, unused] : options.settings)
    if (std::find(engine_names.begin(), engine_names.end(), engine) == engine_names.end())
      throw std::invalid_argument("compare: settings for engine '" + engine +
                                  "', which is not compared here");
  bool any_step = false;
  std::vector<engines::RunOptions> runs;
  std::vector<engines::SettingsRequest> requests;  // runs[i]'s
  for (const auto& engine : engine_names) {
    const engines::EngineSettings* info = engines::find_engine_settings(engine);
    engines::SettingsRequest request;
    request.duration = options.duration;
    if (info && !info->dt_keys.empty()) {
      request.dt = options.dt;
      any_step = true;
    }
    if (info && !info->tolerance_keys.empty()) request.tolerance = options.tolerance;
    if (info && info->solver_key) request.solver = options.solver;
    if (const auto it = options.settings.find(engine); it != options.settings.end())
      request.options = it->second;
    for (const engines::SettingsSet set : options.settings_sets) {
      // An engine without the set runs its defaults, once when they are run anyway.
      if (!engines::applies_settings_set(engine, set) && set != engines::SettingsSet::kDefault &&
          std::find(options.settings_sets.begin(), options.settings_sets.end(),
                    engines::SettingsSet::kDefault) != options.settings_sets.end())
        continue;
      request.set = set;
      runs.push_back(engines::resolve_run_options(engine, s, request));
      requests.push_back(request);
    }
  }
  if (options.dt && !any_step)
    throw std::invalid_argument("compare: --dt given, but none of the engines compared has a step");
  // The event-driven run is the reference trajectory: sampled at the finest compared step.
  if (s.reference_trajectory)
    for (std::size_t i = 0; i < runs.size(); ++i)
      if (runs[i].engine == engine_name::kEvent)
        runs[i] = sampled_as_reference(s, requests[i], runs[i], runs);
  return runs;
}

const EngineRow& CompareReport::row(const std::string& engine) const {
  for (const EngineRow& r : rows)
    if (r.engine == engine) return r;
  throw std::out_of_range("compare: no row for " + engine);
}

bool CompareReport::any_failed() const {
  return std::any_of(rows.begin(), rows.end(),
                     [](const auto& row) { return !row.failure.empty(); });
}

std::vector<std::string> CompareReport::metric_names() const {
  for (const auto& row : rows)
    if (row.failure.empty()) {
      std::vector<std::string> names;
      for (const auto& [name, unused] : row.values) names.push_back(name);
      return names;
    }
  return {};
}

std::string run_label(const engines::RunOptions& options) {
  return options.engine +
         (engines::applies_settings_set(options.engine, options.settings_set) ? " (expert)" : "");
}

std::string settings_text(const engines::RunOptions& options,
                          const engines::SettingList& settings) {
  std::string text = "duration=" + output::number_text(options.duration) + " (" +
                     engines::to_string(options.duration_source) + ")";
  for (const auto& setting : settings)
    text +=
        "; " + setting.key + "=" + setting.value + " (" + engines::to_string(setting.source) + ")";
  return text;
}

namespace {

// Runs one engine; a failure becomes its reason (an interrupt still ends the comparison).
std::optional<engines::RunResult> run_or_fail(const std::string& engine,
                                              const scenario::Scenario& s,
                                              const engines::RunOptions& o, std::string& failure) {
  try {
    return adapters::run_engine(engine, s, o);
  } catch (const ProcessInterrupted&) {
    throw;
  } catch (const std::exception& e) {
    failure = e.what();
    return std::nullopt;
  }
}

// The reference run when the scenario has one and no compared engine provides it: the
// event-driven engine (sampled at the finest step of `runs`), else Moreau–Jean at a tenth of
// the step. Sets report.reference.
std::optional<engines::RunResult> extra_reference_run(const scenario::Scenario& s,
                                                      const CompareOptions& options,
                                                      const std::vector<engines::RunOptions>& runs,
                                                      bool event_compared, CompareReport& report) {
  std::string engine, failure;
  engines::RunOptions o;
  engines::SettingsRequest request;
  request.duration = options.duration;
  if (!event_compared && available(s, engine_name::kEvent)) {
    engine = engine_name::kEvent;
    o = sampled_as_reference(s, request, engines::resolve_run_options(engine, s, request), runs);
    report.reference = engine + " (rtol " + engines::setting_value(o.settings, "rtol") + ")";
  } else if (!event_compared && available(s, engine_name::kMoreau)) {
    engine = engine_name::kMoreau;  // at a tenth of the step it would run with
    request.dt = options.dt;
    const auto nominal = engines::resolve_run_options(engine, s, request);
    request.dt = engines::setting_number(nominal.settings, "dt") / 10.0;
    o = engines::resolve_run_options(engine, s, request);
    report.reference = engine + " (dt " + engines::setting_value(o.settings, "dt") + ")";
  } else {
    report.reference = event_compared ? "none (the event-driven run failed)" : "none";
    return std::nullopt;
  }
  o.recording.progress = options.progress;
  auto run = run_or_fail(engine, s, o, failure);
  if (!run)
    report.reference =
        "none (the reference run, " + report.reference + ", failed: " + failure + ")";
  return run;
}

// The name its CSV files start with: the engine's, `ENGINE_expert` at its expert set.
std::string file_stem(const engines::RunOptions& options) {
  return options.engine +
         (engines::applies_settings_set(options.engine, options.settings_set) ? "_expert" : "");
}

// Why a run asked for a set it does not have is at its defaults; empty otherwise.
std::string set_note(const engines::RunOptions& options) {
  if (options.settings_set == engines::SettingsSet::kDefault ||
      engines::applies_settings_set(options.engine, options.settings_set))
    return "";
  return "no " + engines::to_string(options.settings_set) + " settings set: its defaults";
}

// Why a rise of the energy need not be a gain, for an engine whose contacts hold energy that
// the bodies' kinetic + potential energy leaves out (issue #23, item 6); empty otherwise.
std::string energy_note(const std::string& engine, const NamedValues& values) {
  const auto* info = adapters::find_engine(engine);
  if (!info || info->contact_energy.empty() || !(named_value(values, "energy_max_rise") > 0))
    return "";
  return "energy_drift and energy_max_rise count the bodies' kinetic + potential energy only: " +
         info->contact_energy +
         ", so a rise can be energy its contacts held coming back, not a gain of the scheme";
}

std::string joined_notes(const std::vector<std::string>& notes) {
  std::string text;
  for (const std::string& note : notes)
    if (!note.empty()) text += (text.empty() ? "" : "; ") + note;
  return text;
}

// Removes a failed engine's output files left by an earlier comparison in the same
// directory, so that neither the plots nor a reader take them for this run's.
void remove_stale_outputs(const std::filesystem::path& out, const std::string& stem) {
  for (const char* kind : {"_trajectory.csv", "_events.csv", "_error.csv"})
    std::filesystem::remove(out / (stem + kind));
}

}  // namespace

CompareReport run_compare(const scenario::Scenario& s, const CompareOptions& options) {
  const std::vector<engines::RunOptions> run_options = resolve_compare_runs(s, options);
  std::filesystem::create_directories(options.out);

  std::vector<std::optional<engines::RunResult>> runs;
  std::vector<std::string> failures(run_options.size());
  for (std::size_t i = 0; i < run_options.size(); ++i) {
    engines::RunOptions o = run_options[i];
    o.recording.progress = options.progress;
    const std::string label = run_label(o);
    std::fprintf(stderr, "compare %s: running %s ...\n", s.name.c_str(), label.c_str());
    runs.push_back(run_or_fail(o.engine, s, o, failures[i]));
    if (!runs.back())
      std::fprintf(stderr, "compare %s: %s failed: %s\n", s.name.c_str(), label.c_str(),
                   failures[i].c_str());
  }

  CompareReport report;
  const engines::RunResult* reference = nullptr;
  std::optional<engines::RunResult> extra_reference;
  bool event_compared = false;
  for (std::size_t i = 0; i < runs.size(); ++i)
    if (run_options[i].engine == engine_name::kEvent) {
      event_compared = true;
      if (runs[i]) reference = &*runs[i];
    }
  if (!s.reference_trajectory) {
    reference = nullptr;
    report.reference = "none (the scenario's motion is chaotic: reference_trajectory = false)";
  } else if (reference) {
    report.reference = std::string(engine_name::kEvent) + " (rtol " +
                       engines::setting_value(reference->settings, "rtol") + ")";
  } else {
    extra_reference = extra_reference_run(s, options, run_options, event_compared, report);
    if (extra_reference) reference = &*extra_reference;
  }

  output::Table metrics_table;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string stem = file_stem(run_options[i]);
    if (!runs[i]) {
      remove_stale_outputs(options.out, stem);
      report.rows.push_back(EngineRow{run_label(run_options[i]),
                                      {},
                                      set_note(run_options[i]),
                                      failures[i],
                                      asked_settings_text(run_options[i])});
      continue;
    }
    const engines::RunResult& run = *runs[i];
    std::optional<metrics::PoseTrajectoryError> error;
    if (reference && reference != &run) error = pose_error(run, *reference);
    NamedValues values = run_metrics_with(s, run, error ? &*error : nullptr);
    std::string note =
        joined_notes({run.unconverged_note, run.defect_note,
                      energy_note(run_options[i].engine, values), set_note(run_options[i])});
    EngineRow row{run_label(run_options[i]), std::move(values), std::move(note), "",
                  asked_settings_text(run_options[i])};
    output::write_run_outputs(run.trajectory, run.events, options.out / (stem + "_trajectory.csv"),
                              options.out / (stem + "_events.csv"));
    if (error) write_error_csv(options.out / (stem + "_error.csv"), *error);
    report.rows.push_back(std::move(row));
  }
  metrics_table.columns = report.metric_names();
  metrics_table.columns.insert(metrics_table.columns.begin(), "engine");
  for (const char* last : {"failure", "note", "settings"}) metrics_table.columns.push_back(last);
  for (std::size_t r = 0; r < report.rows.size(); ++r) {
    const auto& row = report.rows[r];
    std::vector<output::TableCell> cells{row.engine};
    for (std::size_t c = 1; c + 3 < metrics_table.columns.size(); ++c) {
      const double value = named_value(row.values, metrics_table.columns[c]);
      // Empty: the metric does not apply (no closed form, no reference, no tolerance), or the
      // run failed.
      cells.push_back(std::isnan(value) ? output::TableCell{std::string()} : value);
    }
    cells.emplace_back(row.failure);
    cells.emplace_back(row.note);
    cells.emplace_back(
        settings_text(run_options[r], runs[r] ? runs[r]->settings : run_options[r].settings));
    metrics_table.rows.push_back(std::move(cells));
  }
  output::write_table_csv(options.out / "metrics.csv", metrics_table);

  if (!options.python.empty()) {
    std::vector<std::string> argv{options.python.string(),
                                  (options.tools_dir / "plot_compare.py").string(),
                                  options.out.string(), s.name};
    for (auto& c : plotted_columns(s)) argv.push_back(c);
    if (run_process(argv, {options.out / "trajectories.png", options.out / "errors.png"}) != 0)
      throw std::runtime_error("compare: plotting failed (" + options.python.string() +
                               " tools/plot_compare.py); is python3-matplotlib installed?");
    for (const char* png : {"trajectories.png", "errors.png"})
      if (std::filesystem::exists(options.out / png))
        report.plots.push_back((options.out / png).string());
  }
  return report;
}

std::string format_report(const CompareReport& report) {
  std::ostringstream out;
  if (report.rows.empty()) return "";
  out << "reference: " << report.reference << "\n";
  char cell[64];
  std::snprintf(cell, sizeof cell, "%-24s", "metric");
  out << cell;
  // 14 characters a column, more for a longer label (`bullet (expert)`).
  const auto width = [](const EngineRow& row) {
    return static_cast<int>(std::max<std::size_t>(14, row.engine.size() + 1));
  };
  for (const auto& row : report.rows) {
    std::snprintf(cell, sizeof cell, "%*s", width(row), row.engine.c_str());
    out << cell;
  }
  out << "\n";
  for (const auto& name : report.metric_names()) {
    std::snprintf(cell, sizeof cell, "%-24s", name.c_str());
    out << cell;
    for (const auto& row : report.rows) {
      if (row.failure.empty())
        std::snprintf(cell, sizeof cell, "%*.4g", width(row), named_value(row.values, name));
      else
        std::snprintf(cell, sizeof cell, "%*s", width(row), "failed");
      out << cell;
    }
    out << "\n";
  }
  for (const auto& row : report.rows)
    if (!row.note.empty()) out << "note (" << row.engine << "): " << row.note << "\n";
  for (const auto& row : report.rows)
    if (!row.failure.empty()) out << "failed (" << row.engine << "): " << row.failure << "\n";
  return out.str();
}

}  // namespace impactbench::compare
