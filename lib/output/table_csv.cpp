#include "lib/output/table_csv.hpp"

#include <stdexcept>

#include "lib/output/atomic_file.hpp"
#include "lib/output/csv_format.hpp"

namespace impactbench::output {

void write_table_csv(const std::filesystem::path& path, const Table& table) {
  for (const auto& row : table.rows)
    if (row.size() != table.columns.size())
      throw std::invalid_argument(path.string() + ": a row has " + std::to_string(row.size()) +
                                  " cells for " + std::to_string(table.columns.size()) +
                                  " columns");
  AtomicFile file(path);
  std::ostream& out = file.stream();
  for (std::size_t i = 0; i < table.columns.size(); ++i) {
    if (i > 0) out << ',';
    write_text(out, table.columns[i]);
  }
  out << '\n';
  for (const auto& row : table.rows) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i > 0) out << ',';
      if (const auto* number = std::get_if<double>(&row[i]))
        write_number(out, *number);
      else
        write_text(out, std::get<std::string>(row[i]));
    }
    out << '\n';
  }
  file.commit();
}

}  // namespace impactbench::output
