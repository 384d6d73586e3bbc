// The only place that knows the scenario file syntax: TOML through toml++, converted to the
// line-annotated DocumentNode tree. toml++ keeps tables sorted by key; the entries are put back
// in file order using each key's source position, so `describe` lists them as written.
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>

#include <toml++/toml.h>

#include "lib/scenario/document.hpp"
#include "lib/scenario/scenario_error.hpp"

namespace impactbench::scenario {

namespace {

// Bounds checked before the parser sees the text: toml++ and convert() recurse once per level
// of a dotted key or table header, so an unbounded line could overflow the stack.
constexpr std::size_t kMaxFileBytes = 10'000'000;
constexpr std::size_t kMaxLineLength = 4096;
constexpr int kMaxNesting = 64;

int line_of(const toml::source_region& region) {
  return static_cast<int>(region.begin.line);
}

DocumentNode convert(const toml::node& node, const std::string& path, int depth) {
  DocumentNode out;
  if (depth > kMaxNesting)
    throw ScenarioError(
        path, line_of(node.source()), "syntax",
        "tables and arrays nested deeper than " + std::to_string(kMaxNesting) + " levels");
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
    for (const auto& item : *array) out.items.push_back(convert(item, path, depth + 1));
  } else if (const auto* table = node.as_table()) {
    out.kind = DocumentNode::Kind::kTable;
    std::vector<std::tuple<toml::source_position, std::string, const toml::node*>> ordered;
    for (const auto& [key, value] : *table)
      ordered.emplace_back(key.source().begin, std::string(key.str()), &value);
    std::stable_sort(ordered.begin(), ordered.end(),
                     [](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
    for (const auto& [position, key, child_node] : ordered) {
      DocumentNode child = convert(*child_node, path, depth + 1);
      // Scalars report the line of their key; tables keep their header line.
      if (child.kind != DocumentNode::Kind::kTable || child.line == 0)
        child.line = static_cast<int>(position.line);
      out.entries.emplace_back(key, std::move(child));
    }
  }
  return out;
}

/// The whole file, after checking its size and the length of every line.
std::string read_bounded(const std::filesystem::path& path) {
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  if (!error && size > kMaxFileBytes)
    throw ScenarioError(
        path.string(), 0, "",
        "file larger than 10 MB (" + std::to_string(size) + " bytes); not a scenario file");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw ScenarioError(path.string(), 0, "", "cannot read the file");
  std::string content = text.str();
  std::size_t line_start = 0;
  for (int line = 1; line_start <= content.size(); ++line) {
    std::size_t end = content.find('\n', line_start);
    if (end == std::string::npos) end = content.size();
    if (end - line_start > kMaxLineLength)
      throw ScenarioError(path.string(), line, "syntax",
                          "line longer than " + std::to_string(kMaxLineLength) + " characters");
    line_start = end + 1;
  }
  return content;
}

}  // namespace

DocumentNode parse_document(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw ScenarioError(path.string(), 0, "", "no such scenario file");
  try {
    const std::string content = read_bounded(path);
    const toml::table root = toml::parse(content, path.string());
    DocumentNode document = convert(root, path.string(), 0);
    document.line = 1;
    return document;
  } catch (const toml::parse_error& parse_error) {
    throw ScenarioError(path.string(), line_of(parse_error.source()), "syntax",
                        std::string(parse_error.description()));
  }
}

}  // namespace impactbench::scenario
