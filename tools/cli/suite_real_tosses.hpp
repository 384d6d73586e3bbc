#pragma once
// The suite's "Real tosses" section: `impactbench validate` of every built engine cube_toss
// lists on the test split of the shipped tosses (the odd numbers; --quick: the first 10 of
// them), at the scenario's default parameters, each run from the toss's first sample. Its
// per_toss.csv and summary.md go to `dir`.
#include <filesystem>
#include <string>

namespace impactbench::cli {

/// The section's Markdown (validate's summary, its headings one level down). Throws what
/// reading the tosses or writing the outputs throws; a run that fails is in the table.
std::string real_tosses_section(bool quick, const std::filesystem::path& dir);

}  // namespace impactbench::cli
