#include "tools/cli/compare_request.hpp"

#include <algorithm>
#include <stdexcept>

#include "tools/cli/command.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/engines/registry/engine_registry.hpp"

namespace impactbench::cli {
namespace {

/// Before anything runs: no engine named twice, every one named can run the scenario.
void check_engines_given(const scenario::Scenario& s, const std::vector<std::string>& engines) {
  for (std::size_t i = 0; i < engines.size(); ++i) {
    const auto here = engines.begin() + static_cast<long>(i);
    if (std::find(engines.begin(), here, engines[i]) != here)
      throw CliError("compare: engine '" + engines[i] + "' is named twice in --engines",
                     kExitUsage);
    if (!s.supports_engine(engines[i]))
      throw CliError("compare: scenario '" + s.name + "' cannot be run by engine '" + engines[i] +
                         "' (its engines: " + engines::join_names(s.engines, "and") + ")",
                     kExitFailure);
  }
}

}  // namespace

compare::CompareOptions compare_options(const scenario::Scenario& s,
                                        const CompareRequest& request) {
  compare::CompareOptions options;
  options.engines = request.engines;
  options.dt = request.dt;
  options.duration = request.duration;
  options.out = request.out;
  options.settings_sets = {settings_set_of(request.settings_set)};
  const auto entries = parse_option_entries(request.options);
  for (const OptionEntry& entry : entries)
    if (entry.engine.empty())
      throw CliError("compare: --option '" + entry.key +
                         "=...' must name its engine (ENGINE.key=value, e.g. moreau." + entry.key +
                         "=...): compare runs several engines",
                     kExitUsage);
  check_engines_given(s, request.engines);
  const auto names = compare::compared_engines(s, request.engines);
  for (const std::string& engine : names) {
    if (const auto* info = adapters::find_engine(engine); info && !info->run)
      throw CliError(adapters::not_built_message(engine), kExitUsage);
    auto given = options_for(entries, engine, false, names);
    if (!given.empty()) options.settings[engine] = std::move(given);
  }
  try {
    compare::resolve_compare_runs(s, options);  // every setting checked before any run
  } catch (const std::invalid_argument& error) {
    throw CliError(error.what(), kExitUsage);
  }
  return options;
}

}  // namespace impactbench::cli
