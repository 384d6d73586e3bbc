// The only place that knows the scenario file syntax: TOML through toml++, converted to the
// line-annotated DocumentNode tree. toml++ keeps tables sorted by key; the entries are put back
// in file order using each key's source position, so `describe` lists them as written.
#include <algorithm>
#include <tuple>

#include <toml++/toml.h>

#include "lib/scenario/document.hpp"
#include "lib/scenario/scenario_error.hpp"

namespace impactbench::scenario {

namespace {

int line_of(const toml::source_region& region) {
  return static_cast<int>(region.begin.line);
}

DocumentNode convert(const toml::node& node) {
  DocumentNode out;
  out.line = line_of(node.source());
  if (const auto* integer = node.as_integer()) {
    out.kind = DocumentNode::Kind::kNumber;
    out.number = static_cast<double>(integer->get());
  } else if (const auto* real = node.as_floating_point()) {
    out.kind = DocumentNode::Kind::kNumber;
    out.number = real->get();
  } else if (const auto* text = node.as_string()) {
    out.kind = DocumentNode::Kind::kString;
    out.text = text->get();
  } else if (const auto* flag = node.as_boolean()) {
    out.kind = DocumentNode::Kind::kBoolean;
    out.boolean = flag->get();
  } else if (const auto* array = node.as_array()) {
    out.kind = DocumentNode::Kind::kArray;
    for (const auto& item : *array) out.items.push_back(convert(item));
  } else if (const auto* table = node.as_table()) {
    out.kind = DocumentNode::Kind::kTable;
    std::vector<std::tuple<toml::source_position, std::string, const toml::node*>> ordered;
    for (const auto& [key, value] : *table)
      ordered.emplace_back(key.source().begin, std::string(key.str()), &value);
    std::stable_sort(ordered.begin(), ordered.end(),
                     [](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
    for (const auto& [position, key, child_node] : ordered) {
      DocumentNode child = convert(*child_node);
      // Scalars report the line of their key; tables keep their header line.
      if (child.kind != DocumentNode::Kind::kTable || child.line == 0)
        child.line = static_cast<int>(position.line);
      out.entries.emplace_back(key, std::move(child));
    }
  }
  return out;
}

}  // namespace

DocumentNode parse_document(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw ScenarioError(path.string(), 0, "", "no such scenario file");
  try {
    const toml::table root = toml::parse_file(path.string());
    DocumentNode document = convert(root);
    document.line = 1;
    return document;
  } catch (const toml::parse_error& parse_error) {
    throw ScenarioError(path.string(), line_of(parse_error.source()), "syntax",
                        std::string(parse_error.description()));
  }
}

}  // namespace impactbench::scenario
