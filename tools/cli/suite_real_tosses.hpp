#pragma once
// The suite's "Real tosses" section: `impactbench validate` of every built engine cube_toss
// lists on the test split of the shipped tosses (the odd numbers; --quick: the first 10 of
// them), each run from the toss's first sample, once at the scenario's default parameters and
// once at each engine's fitted ones (validate --parameters fitted). Their outputs (validate's
// CSV files, summary.md and, with `plots`, its PNG plots; the first test toss traced) go to
// dir/default and dir/fitted.
#include <filesystem>
#include <string>

namespace impactbench::cli {

/// The section's Markdown (its heading, then validate's two summaries, their headings two
/// levels down). Throws what
/// reading the tosses or writing the outputs throws; a run that fails is in the table.
std::string real_tosses_section(bool quick, const std::filesystem::path& dir, bool plots);

}  // namespace impactbench::cli
