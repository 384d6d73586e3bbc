#pragma once
// validate's outputs: per_toss.csv (one row per engine and toss: the metrics, or the reason the
// run failed) and summary.md (per engine and metric: mean, median and 90th percentile over the
// scored tosses, and the failed tosses counted with their reasons). Both appear together or not
// at all (output::commit_together).
#include <filesystem>
#include <string>
#include <vector>

#include "tools/cli/validation_study.hpp"

namespace impactbench::cli {

struct ValidationHeader {
  std::string data;           ///< the data directory, as given
  std::string selection;      ///< --tosses
  std::string initial_state;  ///< sample | fit
  std::string overrides;      ///< --set, as given
  double wall_seconds = 0.0;
};

/// The Markdown summary (also printed on stdout).
std::string validation_summary(const ValidationHeader& header,
                               const std::vector<std::string>& engines,
                               const std::vector<TossRun>& runs);

/// Writes out/per_toss.csv and out/summary.md; throws std::runtime_error when they cannot be
/// written (neither is then left).
void write_validation_outputs(const std::filesystem::path& out, const std::string& summary,
                              const std::vector<TossRun>& runs);

}  // namespace impactbench::cli
