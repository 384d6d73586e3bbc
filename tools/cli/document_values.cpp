#include "tools/cli/document_values.hpp"

#include <cmath>

#include "lib/output/number_text.hpp"
#include "lib/scenario/scenario_error.hpp"

namespace impactbench::cli {

std::string scalar_text(const scenario::DocumentNode& node, const std::filesystem::path& path,
                        const std::string& field) {
  using Kind = scenario::DocumentNode::Kind;
  const auto fail = [&](const std::string& what) {
    return scenario::ScenarioError(path.string(), node.line, field, what);
  };
  switch (node.kind) {
    case Kind::kNumber:
      if (!std::isfinite(node.number)) throw fail("needs a finite number");
      return output::number_text(node.number);
    case Kind::kString:
      if (node.text.empty()) throw fail("needs a non-empty text");
      return node.text;
    case Kind::kBoolean:
      return node.boolean ? "true" : "false";
    default:
      throw fail("needs a number, text or boolean, not a " + scenario::kind_name(node.kind));
  }
}

}  // namespace impactbench::cli
