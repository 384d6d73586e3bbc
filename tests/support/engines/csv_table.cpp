#include "tests/support/engines/csv_table.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace impactbench::test_support {
namespace {

std::vector<std::string> split_record(std::istream& in) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c; in.get(c);) {
    if (quoted) {
      if (c == '"' && in.peek() == '"') {
        fields.back() += '"';
        in.get();
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c == '\n') {
      return fields;
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace

int CsvTable::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
}

const std::string& CsvTable::at(std::size_t row, const std::string& name) const {
  const int index = column(name);
  if (index < 0) throw std::out_of_range("no column " + name);
  return rows.at(row).at(static_cast<std::size_t>(index));
}

CsvTable read_csv_table(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  CsvTable table;
  if (!in) return table;
  table.columns = split_record(in);
  while (in.peek() != std::char_traits<char>::eof()) table.rows.push_back(split_record(in));
  return table;
}

}  // namespace impactbench::test_support
