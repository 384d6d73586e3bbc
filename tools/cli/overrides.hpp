#pragma once
// The --set name=value options shared by describe and run.
#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"

namespace impactbench::cli {

/// Parses every "name=value"; a malformed one or a name given twice throws CliError (usage).
scenario::ParameterOverrides parse_overrides(const std::vector<std::string>& assignments);

}  // namespace impactbench::cli
