#pragma once
// The merge of a sweep: every point's result gathered into one CSV, one row per point (its
// definition, status, reason, reference, engine CPU time and the metrics compare writes for
// its engine). A result of another spec, setting or version is refused with its file's name;
// the points without a result are listed.
#include <filesystem>
#include <string>
#include <vector>

#include "tools/cli/sweep_plan.hpp"

namespace impactbench::cli {

struct MergeOutcome {
  std::size_t rows = 0;
  std::vector<const PlannedPoint*> missing;
};

/// Writes `csv` (atomically) from the results in `dir`; throws CliError (exit 1) naming a
/// result file that is not of this plan or is unreadable, before anything is written.
MergeOutcome merge_sweep(const SweepPlan& plan, const std::filesystem::path& dir,
                         const std::filesystem::path& csv);

}  // namespace impactbench::cli
