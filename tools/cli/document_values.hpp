#pragma once
// Values of the project's TOML files (scenario::DocumentNode) read as the CLI reads them: the
// sweep file and validate's parameter tables share these, and their errors name path:line.
#include <filesystem>
#include <string>

#include "lib/scenario/document.hpp"

namespace impactbench::cli {

/// A number (as output::number_text writes it), a non-empty text or a boolean, as the text a
/// setting takes. Throws scenario::ScenarioError (path:line: field: what) for another kind, a
/// number that is not finite or an empty text.
std::string scalar_text(const scenario::DocumentNode& node, const std::filesystem::path& path,
                        const std::string& field);

}  // namespace impactbench::cli
