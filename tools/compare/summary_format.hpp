#pragma once
// How summary.md writes numbers and tables: counts in full, other values with three digits, a
// missing value as "–", and work-precision points with their failures.
#include <string>
#include <vector>

#include "tools/compare/work_precision.hpp"

namespace impactbench::compare {

/// "–" for NaN, whole numbers below 1e9 in full, else %.3g.
std::string format_value(double value);

/// Text made safe for a Markdown table cell ('|' escaped, newlines as spaces).
std::string markdown_cell(const std::string& text);

/// The table of one work-precision sweep: one row per point, a failed one with its reason.
std::string work_precision_markdown(const std::vector<WorkPoint>& points);

}  // namespace impactbench::compare
