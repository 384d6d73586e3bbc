#include "lib/engines/settings/engine_settings.hpp"

namespace impactbench::engines {

bool EngineSettings::has_key(const std::string& key) const {
  for (const SettingKey& k : keys)
    if (k.key == key) return true;
  return false;
}

std::string EngineSettings::key_list() const {
  std::vector<std::string> names;
  for (const SettingKey& k : keys) names.push_back(k.key);
  return join_names(names, "and");
}

std::string EngineSettings::accepted() const {
  std::vector<std::string> flags;
  if (!dt_keys.empty()) flags.push_back("--dt");
  if (!tolerance_keys.empty()) flags.push_back("--tol");
  if (solver_key) flags.push_back("--solver");
  flags.push_back("--option KEY=VALUE with KEY one of " + key_list());
  return title + " accepts " + join_names(flags, "and");
}

}  // namespace impactbench::engines
