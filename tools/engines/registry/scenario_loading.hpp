#pragma once
// Scenario loading as every program and test does it: the scenario loader with the engine
// registry as its catalog of engines (lib/scenario/engine_catalog.hpp), so that a file's
// `engines` and [settings.ENGINE] are checked against the engines that exist.
#include <filesystem>
#include <optional>
#include <string>

#include "lib/scenario/scenario.hpp"

namespace impactbench::scenario {

/// load_scenario(engine_catalog(), path, ...): throws ScenarioError.
Scenario load_scenario(const std::filesystem::path& path, const ParameterOverrides& overrides = {},
                       std::optional<double> duration = std::nullopt);

/// load_scenario_by_name(engine_catalog(), name, ...): throws ScenarioError.
Scenario load_scenario_by_name(const std::string& name, const ParameterOverrides& overrides = {},
                               std::optional<double> duration = std::nullopt);

}  // namespace impactbench::scenario
