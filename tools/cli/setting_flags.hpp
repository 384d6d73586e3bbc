#pragma once
// The flags `run` and `compare` share for engine settings: a check for finite positive numbers
// (--dt, --tol, --duration) and the reading of `--option [ENGINE.]key=value` entries. Which
// engine a bare key applies to is the command's choice (run: its engine; compare: refused).
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "lib/engines/settings/settings_set.hpp"

namespace impactbench::cli {

/// CLI11's PositiveNumber prints the whole double range and accepts NaN; this says it plainly.
extern const CLI::Validator kPositiveFinite;
/// A finite number >= 0 (e.g. --sample-dt, where 0 means every step).
extern const CLI::Validator kNonNegativeFinite;

/// The name of a settings set (engines::parse_settings_set's refusal as the message).
extern const CLI::Validator kSettingsSetName;
/// Adds `--settings default|expert` (the engines' settings set) to a command; a name that is
/// not a set is refused by the parser (one line, exit 2).
void add_settings_set_option(CLI::App* app, std::string& name);
/// The set `name` names ("" or "default": the defaults); throws CliError (usage) otherwise.
engines::SettingsSet settings_set_of(const std::string& name);

struct OptionEntry {
  std::string engine;  ///< empty for a bare key=value
  std::string key;
  std::string value;
};

/// Reads every entry; throws CliError (usage) for a malformed entry, an unknown engine name or
/// a key given twice for one engine.
std::vector<OptionEntry> parse_option_entries(const std::vector<std::string>& entries);

/// The key=value pairs that apply to `engine`: its own entries, and bare ones when
/// `bare_applies`. Throws CliError (usage) for an entry naming an engine outside `engines`.
std::vector<std::pair<std::string, std::string>> options_for(
    const std::vector<OptionEntry>& entries, const std::string& engine, bool bare_applies,
    const std::vector<std::string>& engines);

}  // namespace impactbench::cli
