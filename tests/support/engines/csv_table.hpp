#pragma once
// A CSV file read back for the CLI tests: its header and rows as text (quoted fields, with
// their commas and doubled quotes, as lib/output/csv_format.hpp writes them).
#include <filesystem>
#include <string>
#include <vector>

namespace impactbench::test_support {

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  /// The column's index; -1 when there is none.
  int column(const std::string& name) const;
  /// The field of `row` in column `name`; throws std::out_of_range when there is no column.
  const std::string& at(std::size_t row, const std::string& name) const;
};

/// An empty table when the file cannot be read.
CsvTable read_csv_table(const std::filesystem::path& path);

}  // namespace impactbench::test_support
