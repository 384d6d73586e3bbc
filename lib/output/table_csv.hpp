#pragma once
// A small table (header + rows of text or numbers) written atomically as CSV: metrics.csv,
// work-precision points, the suite's summaries.
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace impactbench::output {

using TableCell = std::variant<std::string, double>;

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<TableCell>> rows;  ///< each the size of columns
};

/// Throws std::invalid_argument when a row's size differs from the header's, and
/// std::runtime_error when the file cannot be written (then no file is left behind).
void write_table_csv(const std::filesystem::path& path, const Table& table);

}  // namespace impactbench::output
