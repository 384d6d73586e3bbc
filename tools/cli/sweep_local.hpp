#pragma once
// The local executor's run of a planned sweep, shared by `impactbench sweep` and the suite's
// work-precision diagrams: holds the folder's lock, skips the points whose result is there with
// the same hash, and runs the others in the worker pool.
#include <filesystem>
#include <functional>
#include <string>

#include "tools/cli/sweep_plan.hpp"
#include "tools/cli/sweep_pool.hpp"

namespace impactbench::cli {

struct LocalSweepOutcome {
  PoolOutcome pool;
  std::size_t already_done = 0;  ///< points whose valid result was there before this run
};

/// Runs the pending points of `plan` (shard `shard` of `shards` when shards > 0) in a pool as
/// `options` says (its dir is the sweep's folder); `note` gets one line per unreadable or
/// stale result found, before any point runs. Throws CliError when the folder is locked.
LocalSweepOutcome run_local_sweep(const SweepPlan& plan, const PoolOptions& options,
                                  const std::function<void(const std::string&)>& note,
                                  std::size_t shard = 0, std::size_t shards = 0);

/// The machine's cores (at least 1): the default number of workers.
std::size_t default_sweep_jobs();

}  // namespace impactbench::cli
