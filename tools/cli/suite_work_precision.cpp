#include "tools/cli/suite_work_precision.hpp"

#include <cmath>
#include <limits>
#include <map>

#include "lib/output/atomic_file.hpp"
#include "lib/output/number_text.hpp"
#include "tools/cli/progress_line.hpp"
#include "tools/cli/sweep_local.hpp"
#include "tools/cli/sweep_merge.hpp"
#include "tools/cli/sweep_result.hpp"
#include "tools/compare/run_process.hpp"
#include "tools/engines/registry/engine_registry.hpp"

namespace impactbench::cli {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string quoted_list(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "\"" : ", \"") + item + "\"";
  return "[" + text + "]";
}

// The sweep file of one knob: the scenario, the engines and the knob's values.
void write_spec(const fs::path& path, const scenario::Scenario& s, const std::string& quantity,
                const std::string& knob, const std::vector<std::string>& engines, bool quick) {
  std::string values;
  for (const double v : compare::work_precision_values(knob, quick))
    values += (values.empty() ? "" : ", ") + output::number_text(v);
  output::AtomicFile file(path);
  file.stream() << "# impactbench suite: work-precision of " << s.name << " (" << quantity
                << ") over " << knob << "\n"
                << "scenarios = " << quoted_list({s.name}) << "\n"
                << "engines = " << quoted_list(engines) << "\n"
                << "duration = " << output::number_text(s.duration) << "\n"
                << "[grid]\n"
                << (knob == "tol" ? "tolerance" : "dt") << " = [" << values << "]\n";
  file.commit();
}

compare::WorkPoint point_of(const PlannedPoint& planned, const std::string& knob,
                            const std::string& quantity, const fs::path& dir) {
  const SweepPoint& p = planned.point;
  compare::WorkPoint point{p.engine, knob, std::stod(knob == "tol" ? *p.tolerance : *p.dt),
                           kNaN,     kNaN, ""};
  std::string problem;
  const auto result = read_point_result(result_path(dir, p.id), problem);
  if (!result) {
    point.failure = "no result (" + problem + ": its worker ended without one)";
  } else if (result->status != "ok") {
    point.failure = (result->status == "failed" ? "run failed: " : "timed out: ") + result->reason;
  } else {
    for (const auto& [name, value] : result->metrics)
      if (name == quantity && !std::isnan(value)) point.error = std::abs(value);
    if (std::isnan(point.error))
      point.failure = "no " + quantity + " (the run lacks the feature)";
    else
      point.engine_cpu_seconds = result->cpu_seconds;
  }
  return point;
}

}  // namespace

std::vector<compare::WorkPoint> work_precision_by_sweep(
    const scenario::Scenario& s, const std::string& quantity, bool quick, const fs::path& dir,
    const std::function<void(const std::string&)>& note) {
  std::map<std::string, std::vector<std::string>> engines_by_knob;
  for (const auto& info : adapters::engine_registry())
    if (info.run && s.supports_engine(info.name))
      engines_by_knob[compare::work_precision_knob(info.name)].push_back(info.name);
  fs::remove_all(dir);
  std::vector<compare::WorkPoint> points;
  for (const auto& [knob, engines] : engines_by_knob) {
    const fs::path knob_dir = dir / knob;
    fs::create_directories(knob_dir);
    write_spec(knob_dir / "spec.toml", s, quantity, knob, engines, quick);
    const SweepPlan plan = plan_sweep(knob_dir / "spec.toml", false);
    PoolOptions options;
    options.dir = knob_dir;
    options.jobs = default_sweep_jobs();
    options.progress = ProgressLine::stderr_is_terminal();
    if (run_local_sweep(plan, options, note).pool.interrupted)
      throw compare::ProcessInterrupted("work-precision sweep of " + s.name + " interrupted");
    merge_sweep(plan, knob_dir, knob_dir / "sweep.csv");
    for (const PlannedPoint& planned : plan.points) {
      points.push_back(point_of(planned, knob, quantity, knob_dir));
      if (!points.back().failure.empty())
        note(planned.point.engine + " at " + knob + " " + output::number_text(points.back().value) +
             ": " + points.back().failure);
    }
  }
  return points;
}

}  // namespace impactbench::cli
