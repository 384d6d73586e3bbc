#include "tools/cli/overrides.hpp"

#include "tools/cli/command.hpp"

namespace impactbench::cli {

scenario::ParameterOverrides parse_overrides(const std::vector<std::string>& assignments) {
  scenario::ParameterOverrides overrides;
  for (const auto& assignment : assignments) {
    std::pair<std::string, double> parsed;
    try {
      parsed = scenario::parse_override(assignment);
    } catch (const std::invalid_argument& error) {
      throw CliError(error.what(), kExitUsage);
    }
    if (!overrides.insert(parsed).second)
      throw CliError("--set " + parsed.first + " given twice", kExitUsage);
  }
  return overrides;
}

}  // namespace impactbench::cli
