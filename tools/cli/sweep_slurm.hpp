#pragma once
// The Slurm executor: a job-array script in DIR/slurm/ whose task k runs shard k of the points
// (index % shards == k) as `impactbench sweep SPEC --out DIR --shard k/SHARDS --jobs 1`, the
// local executor on that shard, so the points run by the same worker code; submitted with
// sbatch. Only the shards that hold points without a result are submitted, so a resubmission
// reruns exactly the missing points.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "tools/cli/sweep_plan.hpp"

namespace impactbench::cli {

struct SlurmRequest {
  std::filesystem::path spec;        ///< absolute
  std::filesystem::path dir;         ///< absolute
  std::size_t shards = 0;            ///< 0: the spec's, else one per 10 points (at most 1000)
  std::size_t concurrency = 0;       ///< 0: the spec's, else no limit
  std::string time, mem, partition;  ///< empty: the spec's
  double time_limit = 0;             ///< per point, passed to the tasks
  bool force = false;
  bool wait = false;  ///< sbatch --wait
};

/// The shard count used for `plan` and `request`.
std::size_t shard_count(const SweepPlan& plan, const SlurmRequest& request);

/// The array script for the shards in `tasks`.
std::string slurm_script(const SweepPlan& plan, const SlurmRequest& request,
                         const std::vector<std::size_t>& tasks);

/// Writes DIR/slurm/sweep.sbatch and submits it; returns sbatch's exit code (with --wait, that
/// of the job). Prints the job id.
int submit_slurm(const SweepPlan& plan, const SlurmRequest& request,
                 const std::vector<const PlannedPoint*>& pending);

}  // namespace impactbench::cli
