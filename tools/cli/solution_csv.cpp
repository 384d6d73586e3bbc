#include "tools/cli/solution_csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "lib/output/message_text.hpp"
#include "lib/output/table_csv.hpp"
#include "tools/cli/command.hpp"

namespace impactbench::cli {
namespace {

/// Column names of the unknowns (z, or r_n r_t1 …) and of the velocities (w, or u_n u_t1 …).
std::vector<std::string> names(const SolutionShape& shape, const char* letter) {
  if (shape.dimension == 0) return {letter[0] == 'r' ? "z" : "w"};
  std::vector<std::string> columns{std::string(letter) + "_n"};
  if (shape.dimension == 2) {
    columns.push_back(std::string(letter) + "_t");
  } else {
    columns.push_back(std::string(letter) + "_t1");
    columns.push_back(std::string(letter) + "_t2");
  }
  return columns;
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

}  // namespace

void write_solution_csv(const std::filesystem::path& path, const SolutionShape& shape,
                        const solvers::SolverResult& result) {
  output::Table table;
  const int per_row = shape.dimension == 0 ? 1 : shape.dimension;
  table.columns.push_back(shape.dimension == 0 ? "i" : "contact");
  for (const char* letter : {"r", "u"})
    for (const std::string& name : names(shape, letter)) table.columns.push_back(name);
  for (Eigen::Index row = 0; row * per_row < result.solution.size(); ++row) {
    std::vector<output::TableCell> cells{static_cast<double>(row)};
    for (const solvers::CapacityVector* values : {&result.solution, &result.velocity})
      for (int k = 0; k < per_row; ++k) cells.emplace_back((*values)(row * per_row + k));
    table.rows.push_back(std::move(cells));
  }
  output::write_table_csv(path, table);
}

Eigen::VectorXd read_warm_start_csv(const std::filesystem::path& path, const SolutionShape& shape) {
  const std::string where = "--warm-start " + output::printable(path.string(), 200);
  std::ifstream in(path);
  if (!in) throw CliError(where + ": cannot be read", kExitFailure);
  const auto fail = [&](int line, const std::string& what) {
    throw CliError(where + ":" + std::to_string(line) + ": " + what, kExitFailure);
  };
  const int per_row = shape.dimension == 0 ? 1 : shape.dimension;
  const Eigen::Index rows = shape.size / per_row;
  const std::vector<std::string> wanted = names(shape, "r");

  std::string line;
  if (!std::getline(in, line)) fail(1, "empty file, expected a header naming the columns");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::vector<std::string> header = split_fields(line);
  std::vector<std::size_t> columns;
  for (const std::string& name : wanted) {
    std::size_t index = 0;
    while (index < header.size() && header[index] != name) ++index;
    if (index == header.size()) {
      std::string expected;
      for (const std::string& n : wanted) expected += (expected.empty() ? "" : ", ") + n;
      fail(1, "no column '" + name + "' (a solution of this " +
                  (shape.dimension == 0 ? std::string("LCP") : "friction problem") + " has " +
                  expected + ")");
    }
    columns.push_back(index);
  }

  Eigen::VectorXd values(shape.size);
  Eigen::Index row = 0;
  for (int number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (row == rows)
      fail(number, "more rows than the problem's " + std::to_string(rows) +
                       (shape.dimension == 0 ? " unknowns" : " contacts"));
    const std::vector<std::string> fields = split_fields(line);
    if (fields.size() != header.size())
      fail(number, std::to_string(fields.size()) + " fields, the header has " +
                       std::to_string(header.size()));
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const std::string& text = fields[columns[k]];
      double value = 0.0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
      if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        fail(number, wanted[k] + " is not a finite number: '" + output::printable(text, 40) + "'");
      values(row * per_row + static_cast<Eigen::Index>(k)) = value;
    }
    ++row;
  }
  if (in.bad()) throw CliError(where + ": read error", kExitFailure);
  if (row != rows)
    throw CliError(where + ": " + std::to_string(row) + " rows, the problem has " +
                       std::to_string(rows) + (shape.dimension == 0 ? " unknowns" : " contacts"),
                   kExitFailure);
  return values;
}

}  // namespace impactbench::cli
