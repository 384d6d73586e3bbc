#pragma once
// `impactbench suite`: the main job. Runs `compare` on every shipped scenario (piles reduced to
// a size that fits the time budget), work-precision sweeps (Moreau–Jean over step sizes,
// event-driven over tolerances, the reference engines over step sizes; run as sweeps on every
// core, their sweep files and results in OUT/work_precision/SCENARIO/) on the analytical scenarios,
// and the short versions of the benchmark binaries; writes summary.md with the tables and
// diagrams, and the CSVs and PNGs behind them.
#include <filesystem>
#include <functional>
#include <string>

#include "tools/compare/work_precision.hpp"

namespace impactbench::compare {

struct SuiteOptions {
  std::filesystem::path out = "results";
  bool quick = false;                        ///< the 2-minute version: fewer points, no piles
  std::filesystem::path python;              ///< interpreter with matplotlib; empty = no plots
  std::filesystem::path python_for_scripts;  ///< interpreter for the non-plotting scripts
  std::filesystem::path tools_dir;           ///< plot and conversion scripts
  std::filesystem::path bench_dir;  ///< built benchmark binaries; empty or missing = skipped
  /// Runs one scenario's work-precision points (the program runs them as sweeps on every core).
  WorkPrecisionRunner work_precision;
  /// The "Real tosses" section's Markdown, its outputs in `dir` (the program runs validate on
  /// the test split; its plots when `plots`); may throw, and the section then says why it failed.
  std::function<std::string(bool quick, const std::filesystem::path& dir, bool plots)> real_tosses;
};

/// Runs the suite; progress lines go to stderr. Returns the path of summary.md. Throws when an
/// output cannot be written; a failing engine or benchmark is reported in the summary instead.
std::filesystem::path run_suite(const SuiteOptions& options);

}  // namespace impactbench::compare
