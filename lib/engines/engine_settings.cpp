#include "lib/engines/engine_settings.hpp"

#include <cmath>
#include <stdexcept>

namespace impactbench::engines {

double setting_number(const std::string& engine, const std::string& key, const std::string& value) {
  std::size_t used = 0;
  double x = 0.0;
  try {
    x = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (value.empty() || used != value.size() || !std::isfinite(x))
    throw std::invalid_argument(engine + ": setting '" + key + "' is not a finite number: '" +
                                value + "'");
  return x;
}

int setting_int(const std::string& engine, const std::string& key, const std::string& value) {
  const double x = setting_number(engine, key, value);
  if (x != static_cast<double>(static_cast<int>(x)))
    throw std::invalid_argument(engine + ": setting '" + key + "' must be a whole number");
  return static_cast<int>(x);
}

void apply_settings(const std::string& engine, const std::map<std::string, std::string>& given,
                    const std::map<std::string, std::function<void(const std::string&)>>& setters) {
  for (const auto& [key, value] : given) {
    const auto it = setters.find(key);
    if (it == setters.end()) {
      std::string valid;
      for (const auto& [name, unused] : setters) valid += " " + name;
      throw std::invalid_argument(engine + ": unknown setting '" + key + "' (valid:" + valid + ")");
    }
    it->second(value);
  }
}

}  // namespace impactbench::engines
