#include "lib/engines/settings/settings_set.hpp"

#include <stdexcept>

#include "lib/engines/settings/setting_fields.hpp"
#include "lib/output/message_text.hpp"

namespace impactbench::engines {

std::string to_string(SettingsSet set) {
  return set == SettingsSet::kExpert ? "expert" : "default";
}

const std::vector<std::string>& settings_set_names() {
  static const std::vector<std::string> names = {to_string(SettingsSet::kDefault),
                                                 to_string(SettingsSet::kExpert)};
  return names;
}

SettingsSet parse_settings_set(const std::string& name) {
  if (name == to_string(SettingsSet::kDefault)) return SettingsSet::kDefault;
  if (name == to_string(SettingsSet::kExpert)) return SettingsSet::kExpert;
  throw std::invalid_argument("unknown settings set '" + output::printable(name, 60) +
                              "' (sets: " + join_names(settings_set_names()) + ")");
}

}  // namespace impactbench::engines
