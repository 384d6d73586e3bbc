#pragma once
// validate's plots, drawn by tools/plot_validation.py from the CSV files validation_report
// writes: the error against time since the start (median and 90th percentile over tosses), the
// distribution of the per-toss errors over tosses, and one toss's trajectory from each engine
// over the recording.
#include <filesystem>
#include <string>
#include <vector>

namespace impactbench::cli {

/// The PNG files plot_validation writes into the output folder, in that order.
const std::vector<std::string>& validation_plot_names();

/// Draws the plots of the validate outputs in `out` with `python` (an interpreter that has
/// matplotlib) and the scripts of `tools_dir`. Throws std::runtime_error when the script fails
/// (it then leaves no PNG); passes on compare::ProcessInterrupted.
void plot_validation(const std::filesystem::path& python, const std::filesystem::path& tools_dir,
                     const std::filesystem::path& out);

}  // namespace impactbench::cli
