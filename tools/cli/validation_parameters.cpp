#include "tools/cli/validation_parameters.hpp"

#include <cmath>

#include "lib/engines/settings/setting_fields.hpp"
#include "lib/output/number_text.hpp"
#include "lib/resources/resource_paths.hpp"
#include "lib/scenario/document.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "lib/validation/toss_state.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/document_values.hpp"
#include "tools/cli/validation_study.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

using scenario::DocumentNode;
using scenario::ScenarioError;

const DocumentNode& table_of(const DocumentNode& node, const std::filesystem::path& path,
                             const std::string& field) {
  if (node.kind != DocumentNode::Kind::kTable)
    throw ScenarioError(path.string(), node.line, field,
                        "needs a table, not a " + scenario::kind_name(node.kind));
  return node;
}

EngineParameters read_engine(const DocumentNode& node, const std::filesystem::path& path,
                             const std::string& engine) {
  EngineParameters parameters;
  for (const auto& [key, value] : table_of(node, path, engine).entries) {
    const std::string field = engine + "." + key;
    if (key == "set") {
      for (const auto& [name, number] : table_of(value, path, field).entries) {
        const std::string entry = field + "." + name;
        if (number.kind != DocumentNode::Kind::kNumber || !std::isfinite(number.number))
          throw ScenarioError(path.string(), number.line, entry, "needs a finite number");
        if (validation::is_state_parameter(name))
          throw ScenarioError(path.string(), number.line, entry,
                              "is the initial state, which comes from each toss");
        parameters.set[name] = number.number;
      }
    } else if (key == "option") {
      for (const auto& [name, setting] : table_of(value, path, field).entries)
        parameters.options.emplace_back(name, scalar_text(setting, path, field + "." + name));
    } else {
      throw ScenarioError(path.string(), value.line, field, "is not a key (set, option)");
    }
  }
  return parameters;
}

}  // namespace

std::filesystem::path fitted_parameters_path() {
  return resources::cube_toss_directory().parent_path() / "fitted_parameters.toml";
}

ParameterTable read_parameter_table(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw ScenarioError(path.string(), 0, "", "no such parameter file");
  const DocumentNode root = scenario::parse_document(path);
  ParameterTable table;
  for (const auto& [engine, node] : root.entries) {
    if (!adapters::find_engine(engine))
      throw ScenarioError(
          path.string(), node.line, engine,
          "is not an engine (" + engines::join_names(adapters::engine_names()) + ")");
    table[engine] = read_engine(node, path, engine);
  }
  if (table.empty()) throw ScenarioError(path.string(), 0, "", "names no engine");
  return table;
}

std::string apply_parameter_table(ValidationRequest& request, const std::filesystem::path& path) {
  const ParameterTable table = read_parameter_table(path);
  const scenario::Scenario base = scenario::load_scenario_by_name("cube_toss");
  ParameterTable used;
  for (const std::string& engine : request.engines) {
    const auto entry = table.find(engine);
    if (entry == table.end())
      throw CliError("--parameters " + path.string() + ": no [" + engine +
                         "] table (validated: " + engines::join_names(request.engines, "and") + ")",
                     kExitFailure);
    used.insert(*entry);
    request.engine_overrides[engine] = entry->second.set;
    for (const auto& [name, value] : entry->second.set) {
      try {
        base.parameter(name);  // throws naming the valid parameters
      } catch (const std::invalid_argument& error) {
        throw CliError(path.string() + ": [" + engine + "] set." + name + ": " + error.what(),
                       kExitFailure);
      }
    }
    try {
      const scenario::Scenario own =
          scenario::load_scenario_by_name("cube_toss", entry->second.set);
      check_validation_options(own, {{engine, entry->second.options}});
    } catch (const std::exception& error) {
      throw CliError(path.string() + ": [" + engine + "]: " + error.what(), kExitFailure);
    }
    auto& options = request.options[engine];
    options.insert(options.begin(), entry->second.options.begin(), entry->second.options.end());
  }
  return parameter_table_text(used);
}

std::string parameter_table_text(const ParameterTable& table) {
  std::string text;
  for (const auto& [engine, parameters] : table) {
    text += (text.empty() ? "" : "; ") + engine + ":";
    for (const auto& [name, value] : parameters.set)
      text += " " + name + "=" + output::number_text(value);
    for (const auto& [key, value] : parameters.options) text += " " + key + "=" + value;
  }
  return text;
}

}  // namespace impactbench::cli
