#include "tools/cli/sweep_merge.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "lib/engines/settings/settings_set.hpp"
#include "lib/output/table_csv.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/sweep_result.hpp"

namespace impactbench::cli {
namespace {

output::TableCell optional_number(const std::optional<std::string>& text) {
  if (!text) return std::string();
  return std::stod(*text);
}

/// Every file in DIR/points must be a result of one of the plan's points.
void check_foreign_files(const SweepPlan& plan, const std::filesystem::path& dir) {
  const std::filesystem::path points = dir / "points";
  if (!std::filesystem::is_directory(points)) return;
  std::map<std::string, bool> ids;
  for (const PlannedPoint& planned : plan.points) ids[planned.point.id + ".result"] = true;
  for (const auto& entry : std::filesystem::directory_iterator(points))
    if (const std::string name = entry.path().filename().string();
        entry.is_regular_file() && name.front() != '.' && !ids.count(name))
      throw CliError("sweep: " + entry.path().string() + " is not a result of a point of " +
                         plan.spec.path.string() + " (another spec's? merge refused)",
                     kExitFailure);
}

}  // namespace

MergeOutcome merge_sweep(const SweepPlan& plan, const std::filesystem::path& dir,
                         const std::filesystem::path& csv) {
  check_foreign_files(plan, dir);
  MergeOutcome outcome;
  std::vector<std::pair<const PlannedPoint*, PointResult>> found;
  std::vector<std::string> metric_names;
  for (const PlannedPoint& planned : plan.points) {
    const std::filesystem::path path = result_path(dir, planned.point.id);
    std::string problem;
    auto result = read_point_result(path, problem);
    if (!result) {
      if (problem != "missing")
        throw CliError("sweep: " + path.string() + " is " + problem +
                           " (run the sweep again to rerun its point)",
                       kExitFailure);
      outcome.missing.push_back(&planned);
      continue;
    }
    if (result->hash != planned.hash || result->id != planned.point.id)
      throw CliError("sweep: " + path.string() +
                         " was written for another spec, setting or program version (its hash " +
                         result->hash + ", expected " + planned.hash + "); merge refused",
                     kExitFailure);
    for (const auto& [name, unused] : result->metrics)
      if (std::find(metric_names.begin(), metric_names.end(), name) == metric_names.end())
        metric_names.push_back(name);
    found.emplace_back(&planned, std::move(*result));
  }
  output::Table table;
  table.columns = {"id",     "scenario",     "engine",      "dt",      "tolerance",
                   "solver", "settings_set", "sets",        "options", "status",
                   "reason", "reference",    "cpu_seconds", "settings"};
  table.columns.insert(table.columns.end(), metric_names.begin(), metric_names.end());
  for (const auto& [planned, result] : found) {
    const SweepPoint& p = planned->point;
    std::vector<output::TableCell> row = {
        p.id,
        p.scenario,
        p.engine,
        optional_number(p.dt),
        optional_number(p.tolerance),
        p.solver.value_or(""),
        p.settings_set.value_or(engines::to_string(engines::SettingsSet::kDefault)),
        joined(p.sets, ""),
        joined(p.options, ""),
        result.status,
        result.reason,
        result.reference,
        result.cpu_seconds,
        planned->settings};
    for (const std::string& name : metric_names) {
      const auto it = std::find_if(result.metrics.begin(), result.metrics.end(),
                                   [&](const auto& entry) { return entry.first == name; });
      // Empty, as in metrics.csv, where a metric does not apply (NaN).
      if (it == result.metrics.end() || std::isnan(it->second))
        row.emplace_back(std::string());
      else
        row.emplace_back(it->second);
    }
    table.rows.push_back(std::move(row));
  }
  output::write_table_csv(csv, table);
  outcome.rows = table.rows.size();
  return outcome;
}

}  // namespace impactbench::cli
