#include "lib/scenario/document.hpp"

namespace impactbench::scenario {

const DocumentNode* DocumentNode::find(const std::string& key) const {
  for (const auto& [name, node] : entries)
    if (name == key) return &node;
  return nullptr;
}

std::string kind_name(DocumentNode::Kind kind) {
  switch (kind) {
    case DocumentNode::Kind::kNumber:
      return "number";
    case DocumentNode::Kind::kString:
      return "string";
    case DocumentNode::Kind::kBoolean:
      return "boolean";
    case DocumentNode::Kind::kArray:
      return "array";
    case DocumentNode::Kind::kTable:
      return "table";
    case DocumentNode::Kind::kOther:
      break;
  }
  return "date/time";
}

}  // namespace impactbench::scenario
