#include "tools/engines/registry/run_settings.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "lib/engines/step_count.hpp"
#include "lib/output/number_text.hpp"
#include "tools/engines/registry/engine_registry.hpp"

namespace impactbench::engines {
namespace {

std::string source_text(SettingSource source) {
  return "(" + to_string(source) + ")";
}

void refuse_flag(const EngineSettings& info, const std::string& flag) {
  throw std::invalid_argument(info.engine + ": " + flag + " is not a setting of " + info.title +
                              " (" + info.accepted() + ")");
}

}  // namespace

const std::vector<const EngineSettings*>& engine_settings_catalog() {
  static const std::vector<const EngineSettings*> catalog = [] {
    std::vector<const EngineSettings*> out;
    for (const adapters::EngineInfo& info : adapters::engine_registry())
      out.push_back(info.settings);
    return out;
  }();
  return catalog;
}

const EngineSettings* find_engine_settings(const std::string& engine) {
  const adapters::EngineInfo* info = adapters::find_engine(engine);
  return info ? info->settings : nullptr;
}

bool applies_settings_set(const std::string& engine, SettingsSet set) {
  const EngineSettings* info = find_engine_settings(engine);
  return set == SettingsSet::kExpert && info && !info->expert.empty();
}

RunOptions resolve_run_options(const std::string& engine, const scenario::Scenario& s,
                               const SettingsRequest& request) {
  const EngineSettings* info = find_engine_settings(engine);
  if (!info) throw std::invalid_argument("unknown engine '" + engine + "'");
  SettingList given;
  if (request.set == SettingsSet::kExpert)
    for (const auto& [key, value] : info->expert)
      given.push_back({key, value, SettingSource::kExpert});
  const auto add = [&](const std::vector<std::string>& keys, const std::string& value,
                       SettingSource source) {
    for (const std::string& key : keys) given.push_back({key, value, source});
  };
  add(info->dt_keys, output::number_text(s.dt), SettingSource::kScenario);
  add(info->tolerance_keys, output::number_text(s.tolerance), SettingSource::kScenario);
  if (const auto it = s.engine_settings.find(engine); it != s.engine_settings.end())
    for (const auto& [key, value] : it->second)
      given.push_back({key, value, SettingSource::kScenario});

  for (const auto& [key, value] : request.reference_sampling)
    given.push_back({key, value, SettingSource::kReferenceSampling});
  if (request.dt) {
    if (info->dt_keys.empty()) refuse_flag(*info, "--dt");
    add(info->dt_keys, output::number_text(*request.dt), SettingSource::kCommandLine);
  }
  if (request.tolerance) {
    if (info->tolerance_keys.empty()) refuse_flag(*info, "--tol");
    add(info->tolerance_keys, output::number_text(*request.tolerance), SettingSource::kCommandLine);
  }
  if (request.solver) {
    if (!info->solver_key) refuse_flag(*info, "--solver");
    given.push_back(
        {info->solver_key(*request.solver), *request.solver, SettingSource::kCommandLine});
  }
  for (const auto& [key, value] : request.options) {
    if (!info->has_key(key))
      throw SettingError(engine, key, "is unknown (" + info->accepted() + ")");
    given.push_back({key, value, SettingSource::kCommandLine});
  }

  RunOptions options;
  options.engine = engine;
  options.settings_set = request.set;
  ResolvedSettings resolved = info->resolve(given);
  options.settings = std::move(resolved.in_force);
  options.engine_options = std::move(resolved.options);
  options.duration = request.duration.value_or(s.duration);
  options.duration_source =
      request.duration ? SettingSource::kCommandLine : SettingSource::kScenario;
  if (!std::isfinite(options.duration) || !(options.duration > 0.0))
    throw std::invalid_argument("--duration must be a finite number > 0, got " +
                                output::number_text(options.duration));
  for (const SettingValue& setting : options.settings)
    for (const std::string& key : info->dt_keys)
      if (setting.key == key && std::strtod(setting.value.c_str(), nullptr) > options.duration)
        throw std::invalid_argument(engine + ": step " + key + " = " + setting.value + " " +
                                    source_text(setting.source) + " exceeds the duration " +
                                    output::number_text(options.duration) + " " +
                                    source_text(options.duration_source));
  return options;
}

double setting_number(const SettingList& settings, const std::string& key) {
  return std::strtod(setting_value(settings, key).c_str(), nullptr);
}

std::string step_problem(const std::string& engine, double step, double duration) {
  if (step > duration)
    return "step " + output::number_text(step) + " exceeds the duration " +
           output::number_text(duration);
  try {
    checked_step_count(engine, duration, step);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

const std::string& setting_value(const SettingList& settings, const std::string& key) {
  for (const SettingValue& setting : settings)
    if (setting.key == key) return setting.value;
  throw std::out_of_range("no setting '" + key + "'");
}

}  // namespace impactbench::engines
