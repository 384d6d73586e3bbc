#pragma once
// Engine-specific `--option key=value` settings: one parser for every engine, so that a bad
// value or an unknown key reads the same everywhere ("<engine>: unknown setting 'x' (valid: ...)").
#include <functional>
#include <map>
#include <string>

namespace impactbench::engines {

/// A finite number; throws std::invalid_argument naming engine, key and value otherwise.
double setting_number(const std::string& engine, const std::string& key, const std::string& value);
/// A whole number; throws std::invalid_argument naming engine and key otherwise.
int setting_int(const std::string& engine, const std::string& key, const std::string& value);

/// Hands each given key=value to its setter (which receives the value); an unknown key throws
/// std::invalid_argument listing the valid keys.
void apply_settings(const std::string& engine, const std::map<std::string, std::string>& given,
                    const std::map<std::string, std::function<void(const std::string&)>>& setters);

}  // namespace impactbench::engines
