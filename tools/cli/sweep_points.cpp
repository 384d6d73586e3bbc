#include "tools/cli/sweep_points.hpp"

#include <functional>

#include "lib/engines/settings/engine_settings.hpp"
#include "lib/engines/settings/settings_set.hpp"
#include "lib/output/number_text.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "tools/cli/sweep_hash.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"

namespace impactbench::cli {
namespace {

/// The axes that apply to `engine`, in the order of expansion.
struct EngineAxes {
  bool dt = false, tolerance = false, solver = false, settings_set = false;
  std::vector<const SpecAxis*> options;
};

EngineAxes axes_of(const SweepSpec& spec, const std::string& engine) {
  const engines::EngineSettings* info = engines::find_engine_settings(engine);
  EngineAxes axes;
  axes.dt = spec.dt && info && !info->dt_keys.empty();
  axes.tolerance = spec.tolerance && info && !info->tolerance_keys.empty();
  axes.solver = spec.solver && info && info->solver_key;
  if (spec.settings_set)
    for (const SpecValue& value : spec.settings_set->values)
      axes.settings_set = axes.settings_set || engines::applies_settings_set(
                                                   engine, engines::parse_settings_set(value.text));
  for (const SpecAxis& axis : spec.options)
    if (axis.key.rfind(engine + ".", 0) == 0) axes.options.push_back(&axis);
  return axes;
}

double axis_size(const std::optional<SpecAxis>& axis, bool used) {
  return used ? static_cast<double>(axis->values.size()) : 1.0;
}

// A [validate] sweep scores cube_toss runs against recordings: one scenario, and no axis but
// the scenario's parameters and engine options (validate takes no step, tolerance, solver or
// settings set).
void check_validate(const SweepSpec& spec) {
  if (!spec.validate) return;
  const auto refuse = [&](int line, const std::string& field, const std::string& what) {
    throw scenario::ScenarioError(spec.path.string(), line, field, what);
  };
  for (std::size_t i = 0; i < spec.scenarios.size(); ++i)
    if (spec.scenarios[i].text != "cube_toss")
      refuse(spec.scenarios[i].line, "scenarios[" + std::to_string(i) + "]",
             "a [validate] sweep runs cube_toss only, not '" + spec.scenarios[i].text + "'");
  for (const auto* axis : {&spec.dt, &spec.tolerance, &spec.solver, &spec.settings_set})
    if (*axis)
      refuse((*axis)->line, (*axis)->field,
             "a [validate] sweep takes grid.set and grid.option only");
  if (spec.duration)
    refuse(spec.validate->line, "duration",
           "a [validate] sweep runs each toss to its last sample; remove duration");
}

void check_engines(const SweepSpec& spec) {
  const auto names = adapters::engine_names();
  for (std::size_t i = 0; i < spec.engines.size(); ++i)
    if (!engines::find_engine_settings(spec.engines[i].text))
      throw scenario::ScenarioError(spec.path.string(), spec.engines[i].line,
                                    "engines[" + std::to_string(i) + "]",
                                    "unknown engine '" + spec.engines[i].text +
                                        "' (engines: " + engines::join_names(names) + ")");
  for (const SpecAxis& axis : spec.options) {
    const auto dot = axis.key.find('.');
    bool swept = false;
    for (const SpecValue& engine : spec.engines)
      swept = swept || (dot != std::string::npos && axis.key.substr(0, dot) == engine.text);
    if (!swept)
      throw scenario::ScenarioError(
          spec.path.string(), axis.line, axis.field,
          "needs the form \"ENGINE.key\" with an engine of `engines` (e.g. \"moreau.theta\")");
  }
  const auto unused = [&](const std::optional<SpecAxis>& axis,
                          const std::function<bool(const EngineAxes&)>& used) {
    if (!axis) return;
    for (const SpecValue& engine : spec.engines)
      if (used(axes_of(spec, engine.text))) return;
    throw scenario::ScenarioError(spec.path.string(), axis->line, axis->field,
                                  "none of the engines swept uses it");
  };
  unused(spec.dt, [](const EngineAxes& a) { return a.dt; });
  unused(spec.tolerance, [](const EngineAxes& a) { return a.tolerance; });
  unused(spec.solver, [](const EngineAxes& a) { return a.solver; });
  unused(spec.settings_set, [](const EngineAxes& a) { return a.settings_set; });
}

}  // namespace

std::string SweepPoint::definition() const {
  std::string text = "scenario=" + scenario + "; engine=" + engine;
  if (dt) text += "; dt=" + *dt;
  if (tolerance) text += "; tolerance=" + *tolerance;
  if (solver) text += "; solver=" + *solver;
  if (settings_set && *settings_set != engines::to_string(engines::SettingsSet::kDefault))
    text += "; settings=" + *settings_set;
  if (!sets.empty()) text += "; " + joined(sets, "set.");
  if (!options.empty()) text += "; " + joined(options, "option.");
  return text;
}

std::string joined(const std::vector<std::pair<std::string, std::string>>& entries,
                   const std::string& prefix) {
  std::string text;
  for (const auto& [key, value] : entries)
    text += (text.empty() ? "" : "; ") + prefix + key + "=" + value;
  return text;
}

double count_points(const SweepSpec& spec) {
  double sets = 1;
  for (const SpecAxis& axis : spec.sets) sets *= static_cast<double>(axis.values.size());
  double per_scenario = 0;
  for (const SpecValue& engine : spec.engines) {
    const EngineAxes axes = axes_of(spec, engine.text);
    double n = sets * axis_size(spec.dt, axes.dt) * axis_size(spec.tolerance, axes.tolerance) *
               axis_size(spec.solver, axes.solver) *
               axis_size(spec.settings_set, axes.settings_set);
    for (const SpecAxis* axis : axes.options) n *= static_cast<double>(axis->values.size());
    per_scenario += n;
  }
  return per_scenario * static_cast<double>(spec.scenarios.size());
}

std::vector<SweepPoint> expand_points(const SweepSpec& spec, bool force) {
  check_validate(spec);
  check_engines(spec);
  const double total = count_points(spec);
  if (total > static_cast<double>(kMaxPointsUnforced) && !force)
    throw scenario::ScenarioError(spec.path.string(), spec.grid_line, "grid",
                                  "expands to " + output::number_text(total) +
                                      " points, more than " + std::to_string(kMaxPointsUnforced) +
                                      " (give --force to run them)");
  std::vector<SweepPoint> points;
  for (const SpecValue& scenario : spec.scenarios)
    for (const SpecValue& engine : spec.engines) {
      const EngineAxes axes = axes_of(spec, engine.text);
      // The axes of this engine, each a list of (apply) steps, expanded as an odometer.
      std::vector<std::function<void(SweepPoint&, const std::string&)>> apply;
      std::vector<const std::vector<SpecValue>*> lists;
      if (axes.dt) {
        lists.push_back(&spec.dt->values);
        apply.push_back([](SweepPoint& p, const std::string& v) { p.dt = v; });
      }
      if (axes.tolerance) {
        lists.push_back(&spec.tolerance->values);
        apply.push_back([](SweepPoint& p, const std::string& v) { p.tolerance = v; });
      }
      if (axes.solver) {
        lists.push_back(&spec.solver->values);
        apply.push_back([](SweepPoint& p, const std::string& v) { p.solver = v; });
      }
      if (axes.settings_set) {
        lists.push_back(&spec.settings_set->values);
        apply.push_back([](SweepPoint& p, const std::string& v) { p.settings_set = v; });
      }
      for (const SpecAxis& axis : spec.sets) {
        lists.push_back(&axis.values);
        apply.push_back(
            [&axis](SweepPoint& p, const std::string& v) { p.sets.emplace_back(axis.key, v); });
      }
      for (const SpecAxis* axis : axes.options) {
        lists.push_back(&axis->values);
        const std::string key = axis->key.substr(engine.text.size() + 1);
        apply.push_back(
            [key](SweepPoint& p, const std::string& v) { p.options.emplace_back(key, v); });
      }
      std::vector<std::size_t> at(lists.size(), 0);
      while (true) {
        SweepPoint point;
        point.index = points.size();
        point.scenario = scenario.text;
        point.engine = engine.text;
        for (std::size_t i = 0; i < lists.size(); ++i) apply[i](point, (*lists[i])[at[i]].text);
        point.id = hash_text(point.definition());
        points.push_back(std::move(point));
        std::size_t i = lists.size();
        while (i > 0 && ++at[i - 1] == lists[i - 1]->size()) at[--i] = 0;
        if (i == 0) break;
      }
    }
  return points;
}

}  // namespace impactbench::cli
