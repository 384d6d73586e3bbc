#include "tools/compare/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "lib/metrics/contact_criteria.hpp"
#include "lib/metrics/energy_drift.hpp"
#include "lib/metrics/trajectory_error.hpp"
#include "lib/output/run_outputs.hpp"
#include "lib/output/table_csv.hpp"
#include "tools/adapters/engine_registry.hpp"
#include "tools/compare/run_process.hpp"

namespace impactbench::compare {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Positions of a run, each body moved back by the engine's rest offset along the first
// boundary's normal, so that a skin (Box2D) is not counted as trajectory error.
metrics::Signal position_signal(const scenario::Scenario& s, const engines::RunResult& run) {
  metrics::Signal signal;
  const bool planar = s.dimension == scenario::Dimension::kPlanar;
  const int stride = planar ? 3 : 7;
  const Eigen::Vector3d normal =
      s.planes.empty() ? Eigen::Vector3d::Zero() : s.planes.front().normal.normalized();
  for (const auto& sample : run.trajectory.samples) {
    Eigen::VectorXd q = sample.q;
    for (std::size_t i = 0; i < run.rest_offsets.size(); ++i) {
      const int at = stride * static_cast<int>(i);
      if (at + 2 >= q.size()) break;
      if (planar)
        q.segment<2>(at) -= run.rest_offsets[i] * normal.head<2>();
      else
        q.segment<3>(at) -= run.rest_offsets[i] * normal;
    }
    signal.times.push_back(sample.t);
    signal.values.push_back(std::move(q));
  }
  return signal;
}

std::string format_setting(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

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

void write_error_csv(const std::filesystem::path& path, const metrics::TrajectoryError& error) {
  output::Table table{{"t", "error"}, {}};
  for (std::size_t i = 0; i < error.times.size(); ++i)
    table.rows.push_back({error.times[i], error.errors[i]});
  output::write_table_csv(path, table);
}

std::vector<std::string> plotted_columns(const scenario::Scenario& s) {
  if (s.bodies.empty()) return {};
  if (s.system == scenario::SystemKind::kPlankBox)
    return {"box.x", "box.y", "box.theta", "plank.phi"};
  const std::string b = s.bodies.back().name;  // the cradle's last ball; the only body elsewhere
  if (s.dimension == scenario::Dimension::kPlanar) return {b + ".x", b + ".y", b + ".theta"};
  return {b + ".x", b + ".y", b + ".z"};
}

}  // namespace

NamedValues run_metrics(const scenario::Scenario& scenario, const engines::RunResult& run,
                        const engines::RunResult* reference) {
  NamedValues values;
  values.emplace_back("cpu_seconds", run.cpu_seconds);
  values.emplace_back("steps", static_cast<double>(run.steps.size()));
  values.emplace_back("events", static_cast<double>(run.events.size()));
  for (auto& named : analytic_errors(scenario, run)) values.push_back(std::move(named));
  if (reference && reference != &run) {
    const auto error = metrics::trajectory_error(position_signal(scenario, run),
                                                 position_signal(scenario, *reference));
    values.emplace_back("l1_error", error.l1);
    values.emplace_back("linf_error", error.linf);
  } else {
    values.emplace_back("l1_error", kNaN);
    values.emplace_back("linf_error", kNaN);
  }
  const auto criteria = metrics::worst_contact_criteria(run.steps);
  values.emplace_back("max_penetration", criteria.penetration);
  const auto drift = metrics::energy_drift(energies(run));
  values.emplace_back("energy_drift", drift.relative_change);
  values.emplace_back("energy_max_rise", drift.max_rise);
  values.emplace_back("signorini", criteria.signorini);
  values.emplace_back("friction_cone", criteria.friction_cone);
  values.emplace_back("max_dissipation", criteria.max_dissipation);
  values.emplace_back("complementarity", criteria.complementarity);
  return values;
}

CompareReport run_compare(const scenario::Scenario& s, const CompareOptions& options) {
  const std::vector<std::string> engine_names =
      options.engines.empty() ? available_engines(s) : options.engines;
  if (engine_names.empty())
    throw std::invalid_argument("compare: no available engine can run scenario '" + s.name + "'");
  std::filesystem::create_directories(options.out);

  auto run_options = [&](const std::string& engine) {
    engines::RunOptions o;
    o.engine = engine;
    o.dt = options.dt > 0.0 ? options.dt : s.dt;
    o.tolerance = s.tolerance;
    o.duration = options.duration > 0.0 ? options.duration : s.duration;
    if (const auto it = options.settings.find(engine); it != options.settings.end())
      o.settings = it->second;
    return o;
  };

  std::vector<engines::RunResult> runs;
  for (const auto& engine : engine_names) {
    std::fprintf(stderr, "compare %s: running %s ...\n", s.name.c_str(), engine.c_str());
    runs.push_back(adapters::run_engine(engine, s, run_options(engine)));
  }

  CompareReport report;
  const engines::RunResult* reference = nullptr;
  engines::RunResult extra_reference;
  for (const auto& run : runs)
    if (run.engine == "event") reference = &run;
  if (!options.reference) {
    reference = nullptr;
    report.reference = "none (not requested)";
  } else if (reference) {
    report.reference = "event (tol " + format_setting(s.tolerance) + ")";
  } else if (available(s, "event")) {
    extra_reference = adapters::run_engine("event", s, run_options("event"));
    reference = &extra_reference;
    report.reference = "event (tol " + format_setting(s.tolerance) + ")";
  } else if (available(s, "moreau")) {
    auto o = run_options("moreau");
    o.dt /= 10.0;
    extra_reference = adapters::run_engine("moreau", s, o);
    reference = &extra_reference;
    report.reference = "moreau (dt " + format_setting(o.dt) + ")";
  } else {
    report.reference = "none";
  }

  output::Table metrics_table;
  for (const auto& run : runs) {
    EngineRow row{run.engine, run_metrics(s, run, reference)};
    output::write_run_outputs(run.trajectory, run.events,
                              options.out / (run.engine + "_trajectory.csv"),
                              options.out / (run.engine + "_events.csv"));
    if (reference && reference != &run)
      write_error_csv(
          options.out / (run.engine + "_error.csv"),
          metrics::trajectory_error(position_signal(s, run), position_signal(s, *reference)));
    for (const auto& [name, value] : row.values)
      if (std::find(metrics_table.columns.begin(), metrics_table.columns.end(), name) ==
          metrics_table.columns.end())
        metrics_table.columns.push_back(name);
    report.rows.push_back(std::move(row));
  }
  metrics_table.columns.insert(metrics_table.columns.begin(), "engine");
  for (const auto& row : report.rows) {
    std::vector<output::TableCell> cells{row.engine};
    for (std::size_t c = 1; c < metrics_table.columns.size(); ++c) {
      double value = kNaN;
      for (const auto& [name, v] : row.values)
        if (name == metrics_table.columns[c]) value = v;
      cells.emplace_back(value);
    }
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
  for (const auto& row : report.rows) {
    std::snprintf(cell, sizeof cell, "%14s", row.engine.c_str());
    out << cell;
  }
  out << "\n";
  for (std::size_t i = 0; i < report.rows.front().values.size(); ++i) {
    std::snprintf(cell, sizeof cell, "%-24s", report.rows.front().values[i].first.c_str());
    out << cell;
    for (const auto& row : report.rows) {
      const double v = i < row.values.size() ? row.values[i].second : kNaN;
      std::snprintf(cell, sizeof cell, "%14.4g", v);
      out << cell;
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace impactbench::compare
