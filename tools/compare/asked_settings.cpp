#include "tools/compare/asked_settings.hpp"

#include <algorithm>

#include "tools/engines/registry/run_settings.hpp"

namespace impactbench::compare {
namespace {

bool contains(const std::vector<std::string>& keys, const std::string& key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() &&
         text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// The keys that say how hard the engine works and with what: its solver and its limits.
bool is_asked(const engines::EngineSettings& info, const std::string& key) {
  static const std::vector<std::string> choices = {"solver", "stepper", "method", "scheme", "cone"};
  return contains(info.dt_keys, key) || contains(info.tolerance_keys, key) ||
         contains(choices, key) || ends_with(key, "_solver") || ends_with(key, "iterations");
}

}  // namespace

std::string asked_settings_text(const engines::RunOptions& options) {
  const engines::EngineSettings* info = engines::find_engine_settings(options.engine);
  std::string text;
  if (info == nullptr) return text;
  for (const engines::SettingValue& setting : options.settings)
    if (is_asked(*info, setting.key))
      text += (text.empty() ? "" : " ") + setting.key + "=" + setting.value;
  return text;
}

}  // namespace impactbench::compare
