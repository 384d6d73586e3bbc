#pragma once
// A scenario file as a small tree of values that remember their line, so that every later
// check can say where the offending field is. Only document_parser.cpp knows the file syntax
// (TOML, via toml++); the section readers work on this tree.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace impactbench::scenario {

struct DocumentNode {
  enum class Kind { kNumber, kString, kBoolean, kArray, kTable, kOther };

  Kind kind = Kind::kOther;
  int line = 0;                     ///< 1-based line where the value (or table header) starts
  double number = 0.0;              ///< kNumber (integers are converted)
  std::string text;                 ///< kString
  bool boolean = false;             ///< kBoolean
  std::vector<DocumentNode> items;  ///< kArray
  /// kTable, in the order of the file (keys with the line of the key itself).
  std::vector<std::pair<std::string, DocumentNode>> entries;

  const DocumentNode* find(const std::string& key) const;
};

/// "number", "string", "array", ... for messages.
std::string kind_name(DocumentNode::Kind kind);

/// Parses a whole file; throws ScenarioError (path:line: syntax: ...) on a syntax error or an
/// unreadable file.
DocumentNode parse_document(const std::filesystem::path& path);

}  // namespace impactbench::scenario
