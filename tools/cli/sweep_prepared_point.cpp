#include "tools/cli/sweep_prepared_point.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "lib/engines/settings/settings_set.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/compare_request.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/sweep_hash.hpp"
#include "tools/cli/sweep_validate_point.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> assignments(const std::vector<std::pair<std::string, std::string>>& kv,
                                     const std::string& prefix) {
  std::vector<std::string> out;
  for (const auto& [key, value] : kv) out.push_back(prefix + key + "=" + value);
  return out;
}

}  // namespace

std::string program_version() {
  return "impactbench " IMPACTBENCH_VERSION;
}

PreparedPoint prepare_point(const SweepSpec& spec, const SweepPoint& point,
                            const std::filesystem::path& scratch) {
  if (spec.validate) {
    PreparedPoint prepared = prepare_validate_point(spec, point);
    prepared.hash = hash_text(program_version() + "\n" + point.definition() + "\n" +
                              prepared.settings + "\n" + file_text(prepared.scenario.path));
    return prepared;
  }
  PreparedPoint prepared{
      scenario::load_scenario_by_name(point.scenario, parse_overrides(assignments(point.sets, "")),
                                      spec.duration),
      {},
      {},
      {}};
  CompareRequest request;
  request.engines = {point.engine};
  if (point.dt) request.dt = std::stod(*point.dt);
  request.duration = spec.duration;
  request.options = assignments(point.options, point.engine + ".");
  request.out = scratch;
  prepared.options = compare_options(prepared.scenario, request);
  if (point.tolerance) prepared.options.tolerance = std::stod(*point.tolerance);
  prepared.options.solver = point.solver;
  if (point.settings_set)
    prepared.options.settings_sets = {engines::parse_settings_set(*point.settings_set)};
  std::vector<engines::RunOptions> runs;
  try {
    runs = compare::resolve_compare_runs(prepared.scenario, prepared.options);
  } catch (const std::invalid_argument& error) {
    throw CliError(error.what(), kExitUsage);
  }
  prepared.settings = compare::settings_text(runs.front(), runs.front().settings);
  prepared.hash = hash_text(program_version() + "\n" + point.definition() + "\n" +
                            prepared.settings + "\n" + file_text(prepared.scenario.path));
  return prepared;
}

PointResult run_prepared_point(const SweepPoint& point, PreparedPoint& prepared) {
  PointResult result;
  result.id = point.id;
  result.hash = prepared.hash;
  const compare::CompareReport report = compare::run_compare(prepared.scenario, prepared.options);
  std::error_code ignored;
  std::filesystem::remove_all(prepared.options.out, ignored);
  result.reference = report.reference;
  const compare::EngineRow& row = report.rows.front();
  result.status = row.failure.empty() ? "ok" : "failed";
  result.reason = row.failure;
  result.metrics = row.values;
  if (row.failure.empty())
    result.cpu_seconds = compare::named_value(row.values, "engine_cpu_seconds");
  return result;
}

void run_planned_point(const SweepSpec& spec, const SweepPoint& point,
                       const std::filesystem::path& dir) {
  PreparedPoint prepared = prepare_point(spec, point, dir / "scratch" / point.id);
  PointResult result;
  try {
    result = spec.validate ? run_validate_point(spec, point, prepared)
                           : run_prepared_point(point, prepared);
  } catch (const std::exception& error) {
    result = {point.id, prepared.hash, "failed", error.what(), "", 0, {}};
  }
  write_point_result(dir, result);
}

void run_sweep_point(const std::filesystem::path& spec_path, const std::filesystem::path& dir,
                     const std::string& id) {
  const SweepSpec spec = read_sweep_spec(spec_path);
  const std::vector<SweepPoint> points = expand_points(spec, true);
  const auto point =
      std::find_if(points.begin(), points.end(), [&](const SweepPoint& p) { return p.id == id; });
  if (point == points.end())
    throw CliError("sweep-point: " + spec_path.string() + " has no point " + id, kExitUsage);
  run_planned_point(spec, *point, dir);
}

}  // namespace impactbench::cli
