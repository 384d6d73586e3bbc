#include "tools/cli/sweep_local.hpp"

#include <algorithm>
#include <thread>
#include <vector>

#include "tools/cli/sweep_lock.hpp"
#include "tools/cli/sweep_prepared_point.hpp"

namespace impactbench::cli {

LocalSweepOutcome run_local_sweep(const SweepPlan& plan, const PoolOptions& options,
                                  const std::function<void(const std::string&)>& note,
                                  std::size_t shard, std::size_t shards) {
  const SweepLock lock(options.dir, shards > 0);
  LocalSweepOutcome outcome;
  std::vector<std::string> notes;
  const auto pending = pending_points(plan, options.dir, notes, shard, shards);
  for (const std::string& line : notes) note(line);
  std::vector<PoolPoint> work;
  for (const PlannedPoint* planned : pending)
    work.push_back({planned->point.id, planned->hash, [&plan, planned, &options] {
                      run_planned_point(plan.spec, planned->point, options.dir);
                    }});
  outcome.already_done = shards ? 0 : plan.points.size() - pending.size();
  PoolOptions pool_options = options;
  pool_options.shared = shards > 0;
  outcome.pool = run_pool(work, pool_options);
  return outcome;
}

std::size_t default_sweep_jobs() {
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace impactbench::cli
