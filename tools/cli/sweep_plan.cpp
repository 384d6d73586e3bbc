#include "tools/cli/sweep_plan.hpp"

#include <functional>
#include <optional>

#include "lib/scenario/scenario_error.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/sweep_prepared_point.hpp"
#include "tools/cli/sweep_result.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

/// Where in the file a value of the point is: the line and field of `text` on `axis`.
std::optional<std::pair<int, std::string>> place(const std::vector<SpecValue>& values,
                                                 const std::string& field,
                                                 const std::string& text) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (values[i].text == text)
      return std::make_pair(values[i].line, field + "[" + std::to_string(i) + "]");
  return std::nullopt;
}

bool fails(const std::function<void()>& attempt) {
  try {
    attempt();
    return false;
  } catch (const std::exception&) {
    return true;
  }
}

/// The value of the point a failure comes from, found by preparing the point with one value at
/// a time: the scenario alone, each --set, the engine, then each setting.
std::pair<int, std::string> culprit(const SweepSpec& spec, const SweepPoint& point) {
  const std::filesystem::path scratch = "unused";
  SweepPoint probe;
  probe.scenario = point.scenario;
  probe.engine = point.engine;
  if (fails([&] { prepare_point(spec, probe, scratch); })) {
    if (fails([&] { scenario::load_scenario_by_name(point.scenario); }))
      return *place(spec.scenarios, "scenarios", point.scenario);
    return *place(spec.engines, "engines", point.engine);
  }
  for (const auto& [name, value] : point.sets) {
    SweepPoint one = probe;
    one.sets = {{name, value}};
    if (fails([&] { prepare_point(spec, one, scratch); }))
      for (const SpecAxis& axis : spec.sets)
        if (axis.key == name) return *place(axis.values, axis.field, value);
  }
  const auto check =
      [&](const std::optional<std::string>& value, const auto& set_value,
          const std::optional<SpecAxis>& axis) -> std::optional<std::pair<int, std::string>> {
    if (!value) return std::nullopt;
    SweepPoint one = probe;
    set_value(one);
    if (fails([&] { prepare_point(spec, one, scratch); }))
      return place(axis->values, axis->field, *value);
    return std::nullopt;
  };
  if (auto at = check(
          point.dt, [&](SweepPoint& p) { p.dt = point.dt; }, spec.dt))
    return *at;
  if (auto at = check(
          point.tolerance, [&](SweepPoint& p) { p.tolerance = point.tolerance; }, spec.tolerance))
    return *at;
  if (auto at = check(
          point.solver, [&](SweepPoint& p) { p.solver = point.solver; }, spec.solver))
    return *at;
  for (const auto& [key, value] : point.options) {
    SweepPoint one = probe;
    one.options = {{key, value}};
    if (fails([&] { prepare_point(spec, one, scratch); }))
      for (const SpecAxis& axis : spec.options)
        if (axis.key == point.engine + "." + key) return *place(axis.values, axis.field, value);
  }
  return {0, "point " + point.definition()};
}

}  // namespace

SweepPlan plan_sweep(const std::filesystem::path& spec_path, bool force) {
  SweepPlan plan;
  try {
    plan.spec = read_sweep_spec(spec_path);
    std::vector<SweepPoint> points = expand_points(plan.spec, force);
    for (SweepPoint& point : points) {
      try {
        const PreparedPoint prepared = prepare_point(plan.spec, point, "unused");
        plan.points.push_back({std::move(point), prepared.hash, prepared.settings});
      } catch (const std::exception& error) {
        const auto [line, field] = culprit(plan.spec, point);
        throw scenario::ScenarioError(spec_path.string(), line, field, error.what());
      }
    }
  } catch (const scenario::ScenarioError& error) {
    throw CliError(error.what(), kExitFailure);
  }
  return plan;
}

std::vector<const PlannedPoint*> pending_points(const SweepPlan& plan,
                                                const std::filesystem::path& dir,
                                                std::vector<std::string>& notes, std::size_t shard,
                                                std::size_t shards) {
  std::vector<const PlannedPoint*> pending;
  for (const PlannedPoint& planned : plan.points) {
    if (shards > 0 && planned.point.index % shards != shard) continue;
    const std::filesystem::path path = result_path(dir, planned.point.id);
    std::string problem;
    const auto result = read_point_result(path, problem);
    if (result && result->hash == planned.hash && result->id == planned.point.id) continue;
    if (result)
      notes.push_back(path.string() + ": written for other settings or another version; rerun");
    else if (problem != "missing")
      notes.push_back(path.string() + ": " + problem + "; rerun");
    pending.push_back(&planned);
  }
  return pending;
}

}  // namespace impactbench::cli
