#pragma once
// Plain-text LCP files (w = M z + q, 0 ≤ z ⊥ w ≥ 0), meant to be written and read by hand.
//
//   # anything after '#' is a comment; blank lines are ignored
//   lcp <n> dense            header: size n ≥ 1 and the storage of M ("dense" or "sparse")
//   q_1 q_2 ... q_n          one line: the n entries of q
//   M_11 M_12 ... M_1n       dense: exactly n lines of n entries, row by row
//   ...
//   M_n1 M_n2 ... M_nn
//
// or, for "sparse", after the q line any number of lines (including none) of the form
//
//   i j value                0-based row i and column j of a stored entry of M
//
// Each (i, j) may appear once. Numbers are decimal floating point; NaN and Inf are rejected.
// Example (n = 2, dense):  "lcp 2 dense\n-1 -1\n2 1\n1 2\n".
#include <filesystem>

#include "solvers/lcp/lcp_problem.hpp"

namespace impactbench::solvers::io {

/// Reads a problem. Throws std::runtime_error "<path>:<line>: <what is wrong>" on any error
/// (missing file, bad header, wrong number of entries, a token that is not a finite number,
/// an index out of range or repeated, text after the last dense row).
LcpProblem read_lcp_file(const std::filesystem::path& path);

/// Writes `problem` in the format above with 17 significant digits (an exact round trip).
/// Writes to a temporary file in the same directory and renames it over `path`, so readers
/// never see a partial file. Throws std::runtime_error naming the path on failure, and
/// std::invalid_argument if the problem has inconsistent sizes or non-finite entries.
void write_lcp_file(const std::filesystem::path& path, const LcpProblem& problem);

}  // namespace impactbench::solvers::io
