#pragma once
// validate's outputs: per_toss.csv (one row per engine and toss: the metrics, or the reason the
// run failed), summary.md (per engine and metric: mean, median and 90th percentile over the
// scored tosses, and the failed tosses counted with their reasons), error_over_time.csv (per
// engine, the position and rotation errors' statistics over tosses in bins of time since the
// start) and toss_trajectory.csv (one toss's recorded poses and every engine's simulated ones at
// the same times). They appear together or not at all (output::commit_together).
#include <filesystem>
#include <string>
#include <vector>

#include "tools/cli/validation_study.hpp"

namespace impactbench::cli {

struct ValidationHeader {
  std::string data;                       ///< the data directory, as given
  std::string selection;                  ///< --tosses
  std::string initial_state;              ///< sample | fit
  std::string parameter_set = "default";  ///< --parameters: default, fitted or a file
  std::string table;                      ///< its entries, as parameter_table_text gives them
  std::string overrides;                  ///< --set, as given
  double wall_seconds = 0.0;
};

/// The Markdown summary (also printed on stdout).
std::string validation_summary(const ValidationHeader& header,
                               const std::vector<std::string>& engines,
                               const std::vector<TossRun>& runs);

/// The width of error_over_time.csv's bins: about three samples at the data's 148 Hz.
inline constexpr double kErrorBinSeconds = 0.02;

/// The files write_validation_outputs writes, in that order.
const std::vector<std::string>& validation_output_names();

/// Writes validation_output_names() into `out`; `traced` is the toss whose poses the runs kept
/// (ValidationRequest::traced_toss). Throws std::runtime_error when they cannot be written (none
/// is then left).
void write_validation_outputs(const std::filesystem::path& out, const std::string& summary,
                              const std::vector<std::string>& engines,
                              const std::vector<TossRun>& runs, const validation::Toss& traced);

}  // namespace impactbench::cli
