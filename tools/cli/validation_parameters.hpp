#pragma once
// validate's parameter tables (--parameters): per engine, cube_toss parameters and engine
// settings to run it with. The shipped one, scenarios/data/cube_toss/fitted_parameters.toml,
// holds each engine's fit on the training split (docs/real-tosses.md#fitted-parameters):
//
//   [mujoco]
//   set = { friction = 0.2, restitution = 0.05 }
//   option = { solimp_dmin = 0.95 }
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lib/scenario/scenario.hpp"

namespace impactbench::cli {

struct EngineParameters {
  scenario::ParameterOverrides set;                          ///< cube_toss parameters
  std::vector<std::pair<std::string, std::string>> options;  ///< engine settings, key=value
};

/// engine → its parameters.
using ParameterTable = std::map<std::string, EngineParameters>;

/// The shipped table of fitted parameters.
std::filesystem::path fitted_parameters_path();

/// Reads a parameter table. Throws scenario::ScenarioError (path:line: field: what) for a file
/// that is not TOML, an entry that is not a table named after a known engine, a key other than
/// `set` and `option`, a `set` value that is not a finite number or names an initial-state
/// parameter, and an option value that is not a number, text or boolean.
ParameterTable read_parameter_table(const std::filesystem::path& path);

struct ValidationRequest;

/// Gives each engine of `request` its entry of the table at `path` (its parameters under the
/// request's overrides, its options before the request's). Returns parameter_table_text of the
/// entries used. Throws CliError (exit 1) naming the file for an engine without an entry, a
/// parameter cube_toss does not have or refuses, or an option its engine refuses; what
/// read_parameter_table throws for a bad file.
std::string apply_parameter_table(ValidationRequest& request, const std::filesystem::path& path);

/// "engine: name=value ...; engine: ..." for the report.
std::string parameter_table_text(const ParameterTable& table);

}  // namespace impactbench::cli
