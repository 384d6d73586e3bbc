#include "tools/cli/setting_flags.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "lib/engines/settings/setting_fields.hpp"
#include "lib/output/message_text.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/cli/command.hpp"
#include "tools/engines/registry/engine_registry.hpp"

namespace impactbench::cli {
namespace {
/// A flag's number, finite and above `lower` (or at least it, when `inclusive`).
CLI::Validator finite_number_above(double lower, bool inclusive, const std::string& name) {
  const std::string wanted = std::string(inclusive ? ">= " : "> ") + output::number_text(lower);
  return CLI::Validator(
      [lower, inclusive, wanted](std::string& text) {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !std::isfinite(value) ||
            !(inclusive ? value >= lower : value > lower))
          return "must be a finite number " + wanted + ", got '" + output::printable(text, 60) +
                 "'";
        return std::string();
      },
      name);
}
}  // namespace

const CLI::Validator kPositiveFinite = finite_number_above(0.0, false, "POSITIVE");
const CLI::Validator kNonNegativeFinite = finite_number_above(0.0, true, "NON-NEGATIVE");

const CLI::Validator kSettingsSetName(
    [](std::string& text) {
      try {
        engines::parse_settings_set(text);
      } catch (const std::invalid_argument& error) {
        return std::string(error.what());
      }
      return std::string();
    },
    "SET");

void add_settings_set_option(CLI::App* app, std::string& name) {
  app->add_option("--settings", name,
                  "Settings set: default (each engine's defaults) or expert (each reference "
                  "engine's values from its own documentation for accurate rigid contact, over "
                  "its defaults and under the scenario and --option; our engines have none and "
                  "run their defaults) (default: default)")
      ->check(kSettingsSetName);
}

engines::SettingsSet settings_set_of(const std::string& name) {
  if (name.empty()) return engines::SettingsSet::kDefault;
  try {
    return engines::parse_settings_set(name);
  } catch (const std::invalid_argument& error) {
    throw CliError(error.what(), kExitUsage);
  }
}

std::vector<OptionEntry> parse_option_entries(const std::vector<std::string>& entries) {
  std::vector<OptionEntry> out;
  const auto& known = adapters::engine_names();
  for (const std::string& entry : entries) {
    const auto equals = entry.find('=');
    if (equals == std::string::npos || equals == 0)
      throw CliError("--option '" + output::printable(entry, 60) + "' is not [ENGINE.]key=value",
                     kExitUsage);
    OptionEntry parsed{"", entry.substr(0, equals), entry.substr(equals + 1)};
    if (const auto dot = parsed.key.find('.'); dot != std::string::npos) {
      parsed.engine = parsed.key.substr(0, dot);
      parsed.key = parsed.key.substr(dot + 1);
      if (std::find(known.begin(), known.end(), parsed.engine) == known.end())
        throw CliError("--option '" + output::printable(entry, 60) + "': unknown engine '" +
                           output::printable(parsed.engine, 60) +
                           "' (engines: " + engines::join_names(known) + ")",
                       kExitUsage);
      if (parsed.key.empty())
        throw CliError("--option '" + output::printable(entry, 60) + "' names no key", kExitUsage);
    }
    for (const OptionEntry& earlier : out)
      if (earlier.engine == parsed.engine && earlier.key == parsed.key)
        throw CliError("--option " + (parsed.engine.empty() ? "" : parsed.engine + ".") +
                           output::printable(parsed.key, 60) + " given twice",
                       kExitUsage);
    out.push_back(std::move(parsed));
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> options_for(
    const std::vector<OptionEntry>& entries, const std::string& engine, bool bare_applies,
    const std::vector<std::string>& engines) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const OptionEntry& entry : entries) {
    if (!entry.engine.empty() &&
        std::find(engines.begin(), engines.end(), entry.engine) == engines.end())
      throw CliError("--option " + entry.engine + "." + output::printable(entry.key, 60) +
                         ": engine '" + entry.engine +
                         "' is not run here (engines: " + engines::join_names(engines, "and") + ")",
                     kExitUsage);
    if (entry.engine != engine && !(entry.engine.empty() && bare_applies)) continue;
    for (const auto& [key, value] : out)
      if (key == entry.key)
        throw CliError(
            "--option " + output::printable(entry.key, 60) + " given twice for " + engine,
            kExitUsage);
    out.emplace_back(entry.key, entry.value);
  }
  return out;
}

}  // namespace impactbench::cli
