// [settings.ENGINE]: engine settings a scenario chooses (format: scenarios/README.md). Each
// key and value is checked here against the engine's own settings (through the engine
// catalog), so that a misspelt key or a value out of range is refused with path:line: field
// like every other mistake in the file.
#include <algorithm>

#include "lib/output/number_text.hpp"
#include "lib/scenario/load_context.hpp"

namespace impactbench::scenario {

std::map<std::string, std::vector<std::pair<std::string, std::string>>> read_engine_settings(
    const LoadContext& context, const TableReader& root, const Scenario& scenario) {
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> out;
  const DocumentNode* section = root.optional("settings");
  if (!section) return out;
  const TableReader must_be_a_table(context, *section, "settings.");
  const std::vector<std::string>& known_engines = context.engines->engine_names();
  for (const auto& [engine, node] : section->entries) {
    const std::string field = "settings." + engine;
    if (std::find(known_engines.begin(), known_engines.end(), engine) == known_engines.end()) {
      std::string known;
      for (const auto& name : known_engines) known += (known.empty() ? "" : ", ") + name;
      context.fail(node.line, field, "unknown engine '" + engine + "' (known: " + known + ")");
    }
    if (!scenario.supports_engine(engine))
      context.fail(node.line, field, "engine '" + engine + "' is not in this scenario's engines");
    const TableReader table(context, node, field + ".");
    auto& settings = out[engine];
    for (const auto& [key, value] : node.entries) {
      std::string text;
      if (value.kind == DocumentNode::Kind::kNumber)
        text = output::number_text(value.number);
      else if (value.kind == DocumentNode::Kind::kString)
        text = value.text;
      else if (value.kind == DocumentNode::Kind::kBoolean)
        text = value.boolean ? "true" : "false";
      else
        context.fail(value.line, table.field(key),
                     "expected a number, a string or true/false, got " + kind_name(value.kind));
      const std::string problem =
          context.engines->setting_problem(engine, key, text, scenario.duration);
      if (!problem.empty()) context.fail(value.line, table.field(key), problem);
      settings.emplace_back(key, text);
    }
  }
  return out;
}

}  // namespace impactbench::scenario
