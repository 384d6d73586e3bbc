#pragma once
// What a sweep will do, decided before any point runs: the spec read and expanded, every point
// prepared (so that a bad scenario, engine or value is refused with the line of the file that
// gives it) and its hash known, and the points whose result in DIR is missing, stale (another
// hash) or unreadable.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "tools/cli/sweep_points.hpp"
#include "tools/cli/sweep_spec.hpp"

namespace impactbench::cli {

struct PlannedPoint {
  SweepPoint point;
  std::string hash;
  std::string settings;  ///< the settings in force, as in compare's metrics.csv
};

struct SweepPlan {
  SweepSpec spec;
  std::vector<PlannedPoint> points;
};

/// Reads, expands and prepares; throws CliError (exit 1) with `path:line: field: what`.
SweepPlan plan_sweep(const std::filesystem::path& spec_path, bool force);

/// The points of `plan` (those of shard k of n when n > 0: index % n == k) without a valid
/// result of their hash in `dir`; `notes` gets one line per unreadable or stale result.
std::vector<const PlannedPoint*> pending_points(const SweepPlan& plan,
                                                const std::filesystem::path& dir,
                                                std::vector<std::string>& notes,
                                                std::size_t shard = 0, std::size_t shards = 0);

}  // namespace impactbench::cli
