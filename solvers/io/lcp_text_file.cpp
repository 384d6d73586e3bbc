#include "solvers/io/lcp_text_file.hpp"
#include "solvers/common/number_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace impactbench::solvers::io {
namespace {

// One non-empty line with comments removed, split into whitespace-separated tokens.
struct Line {
  int number = 0;
  std::vector<std::string> tokens;
};

class LineReader {
 public:
  explicit LineReader(const std::filesystem::path& path) : path_(path), in_(path) {
    if (!in_) throw std::runtime_error(path_.string() + ": cannot open file for reading");
  }

  // The next line with at least one token; false at end of file.
  bool next(Line& line) {
    std::string text;
    while (std::getline(in_, text)) {
      ++number_;
      if (const auto hash = text.find('#'); hash != std::string::npos) text.erase(hash);
      std::istringstream split(text);
      line.tokens.clear();
      for (std::string token; split >> token;) line.tokens.push_back(std::move(token));
      if (!line.tokens.empty()) {
        line.number = number_;
        return true;
      }
    }
    return false;
  }

  [[noreturn]] void fail(int line, const std::string& what) const {
    throw std::runtime_error(path_.string() + ":" + std::to_string(line) + ": " + what);
  }
  // Where a "file ends too early" error is reported: the last line (1 for an empty file).
  int end_line() const { return std::max(1, number_); }

  double number(const Line& line, std::size_t k, const char* what) const {
    const std::string& token = line.tokens[k];
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size()) {
      fail(line.number, std::string(what) + " '" + token + "' is not a number");
    }
    if (!std::isfinite(value))
      fail(line.number, std::string(what) + " '" + token + "' is not finite");
    return value;
  }

  int index(const Line& line, std::size_t k, const char* what, int n) const {
    const std::string& token = line.tokens[k];
    int value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size()) {
      fail(line.number, std::string(what) + " '" + token + "' is not an integer");
    }
    if (value < 0 || value >= n) {
      fail(line.number,
           std::string(what) + " " + token + " is out of range [0, " + std::to_string(n) + ")");
    }
    return value;
  }

  void expect_count(const Line& line, std::size_t count, const std::string& what) const {
    if (line.tokens.size() != count) {
      fail(line.number, "expected " + std::to_string(count) + " " + what + ", found " +
                            std::to_string(line.tokens.size()));
    }
  }

 private:
  std::filesystem::path path_;
  std::ifstream in_;
  int number_ = 0;
};

bool all_finite(const LcpProblem& problem) {
  if (!problem.q.allFinite()) return false;
  if (!problem.is_sparse) return problem.dense_M.allFinite();
  for (int i = 0; i < problem.sparse_M.outerSize(); ++i) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(problem.sparse_M, i); it;
         ++it) {
      if (!std::isfinite(it.value())) return false;
    }
  }
  return true;
}

}  // namespace

LcpProblem read_lcp_file(const std::filesystem::path& path) {
  LineReader reader(path);
  Line line;
  if (!reader.next(line))
    reader.fail(reader.end_line(),
                "file ends before the header; expected header 'lcp <n> dense|sparse'");
  if (line.tokens.size() != 3 || line.tokens[0] != "lcp" ||
      (line.tokens[2] != "dense" && line.tokens[2] != "sparse")) {
    reader.fail(line.number, "expected header 'lcp <n> dense|sparse'");
  }
  int n = 0;
  {
    const std::string& token = line.tokens[1];
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), n);
    if (error != std::errc() || end != token.data() + token.size() || n < 1) {
      reader.fail(line.number, "size '" + token + "' is not a positive integer");
    }
  }
  const bool sparse = line.tokens[2] == "sparse";
  const auto count = static_cast<std::size_t>(n);

  if (!reader.next(line)) reader.fail(reader.end_line(), "file ends before the line of q");
  reader.expect_count(line, count, "entries of q");
  Eigen::VectorXd q(n);
  for (int i = 0; i < n; ++i) q(i) = reader.number(line, i, "q entry");

  if (!sparse) {
    Eigen::MatrixXd M(n, n);
    for (int i = 0; i < n; ++i) {
      if (!reader.next(line)) {
        reader.fail(reader.end_line(), "file ends after " + std::to_string(i) +
                                           " rows of dense M, expected " + std::to_string(n));
      }
      reader.expect_count(line, count, "entries in row " + std::to_string(i) + " of M");
      for (int j = 0; j < n; ++j) M(i, j) = reader.number(line, j, "M entry");
    }
    if (reader.next(line)) reader.fail(line.number, "unexpected text after the last row of M");
    return LcpProblem::dense(std::move(M), std::move(q));
  }

  std::vector<Eigen::Triplet<double>> entries;
  std::set<std::pair<int, int>> seen;
  while (reader.next(line)) {
    reader.expect_count(line, 3, "values 'i j value'");
    const int i = reader.index(line, 0, "row index", n);
    const int j = reader.index(line, 1, "column index", n);
    if (!seen.emplace(i, j).second) {
      reader.fail(line.number,
                  "entry (" + std::to_string(i) + ", " + std::to_string(j) + ") appears twice");
    }
    entries.emplace_back(i, j, reader.number(line, 2, "M entry"));
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> M(n, n);
  M.setFromTriplets(entries.begin(), entries.end());
  M.makeCompressed();
  return LcpProblem::sparse(std::move(M), std::move(q));
}

void write_lcp_file(const std::filesystem::path& path, const LcpProblem& problem) {
  const Eigen::Index n = problem.q.size();
  const Eigen::Index rows = problem.is_sparse ? problem.sparse_M.rows() : problem.dense_M.rows();
  const Eigen::Index cols = problem.is_sparse ? problem.sparse_M.cols() : problem.dense_M.cols();
  if (n < 1 || rows != n || cols != n) {
    throw std::invalid_argument("write_lcp_file " + path.string() + ": M is " +
                                std::to_string(rows) + "x" + std::to_string(cols) + " but q has " +
                                std::to_string(n) + " entries");
  }
  if (!all_finite(problem)) {
    throw std::invalid_argument("write_lcp_file " + path.string() +
                                ": the problem has NaN or Inf entries");
  }

  std::ostringstream text;
  text << "lcp " << n << (problem.is_sparse ? " sparse\n" : " dense\n");
  for (Eigen::Index i = 0; i < n; ++i) text << (i ? " " : "") << output::number_text(problem.q(i));
  text << '\n';
  if (problem.is_sparse) {
    for (int i = 0; i < problem.sparse_M.outerSize(); ++i) {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(problem.sparse_M, i); it;
           ++it) {
        text << it.row() << ' ' << it.col() << ' ' << output::number_text(it.value()) << '\n';
      }
    }
  } else {
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = 0; j < n; ++j) {
        text << (j ? " " : "") << output::number_text(problem.dense_M(i, j));
      }
      text << '\n';
    }
  }

  // Temporary next to the target (same file system, so the rename is atomic).
  std::filesystem::path temporary = path;
  temporary += ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text.str();
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error(path.string() + ": cannot write LCP file");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error(path.string() + ": cannot replace file (" + error.message() + ")");
  }
}

}  // namespace impactbench::solvers::io
