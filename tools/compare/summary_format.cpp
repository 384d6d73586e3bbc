#include "tools/compare/summary_format.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace impactbench::compare {

std::string format_value(double v) {
  if (std::isnan(v)) return "–";
  char text[32];
  // Counts (steps, events) in full; %.3g would print 1000 as 1e+03.
  if (v == std::round(v) && std::abs(v) < 1e9)
    std::snprintf(text, sizeof text, "%.0f", v);
  else
    std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

std::string markdown_cell(const std::string& text) {
  std::string cell;
  for (const char c : text) {
    if (c == '|') cell += '\\';
    cell += c == '\n' ? ' ' : c;
  }
  return cell;
}

std::string work_precision_markdown(const std::vector<WorkPoint>& points) {
  std::ostringstream md;
  md << "| engine | setting | value | error | engine CPU [s] |\n|---|---|---:|---:|---:|\n";
  for (const auto& p : points) {
    md << "| " << p.engine << " | " << p.setting << " | " << format_value(p.value) << " | ";
    if (p.failure.empty())
      md << format_value(p.error) << " | " << format_value(p.engine_cpu_seconds) << " |\n";
    else
      md << "**failed:** " << markdown_cell(p.failure) << " | – |\n";
  }
  return md.str();
}

}  // namespace impactbench::compare
