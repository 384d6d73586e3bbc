#pragma once
// The local executor: a pool of worker processes, each a fork of the pool's process running one
// point with the job it is given (the sweep's: run_planned_point, which
// `impactbench sweep-point SPEC --out DIR --id ID` and every other executor's workers run), at most
// `jobs` at a time. A point that passes its time limit is killed and recorded as timed out; a
// worker that dies otherwise leaves no result, so a resume reruns it. On SIGINT or SIGTERM no new
// point starts, the workers are ended and no result is half written (results are published
// atomically).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace impactbench::cli {

struct PoolPoint {
  std::string id;
  std::string hash;           ///< for the timeout result the pool writes itself
  std::function<void()> run;  ///< the worker's job: runs the point and writes its result
};

struct PoolOptions {
  std::filesystem::path dir;
  std::size_t jobs = 1;
  double time_limit = 0;  ///< seconds per point; 0: none
  bool progress = false;
  /// Other pools (the shards of a Slurm array) run in `dir` at the same time: the pool leaves
  /// the shared logs/ and scratch/ folders in place, since removing them, even empty, can pull
  /// them from under another pool's worker about to write there.
  bool shared = false;
};

struct PoolOutcome {
  std::size_t ran = 0;       ///< points with a result written in this run
  std::size_t failed = 0;    ///< of which failed or timed out
  std::size_t lost = 0;      ///< workers that ended without a result (rerun on resume)
  bool interrupted = false;  ///< ended by SIGINT or SIGTERM
};

PoolOutcome run_pool(const std::vector<PoolPoint>& points, const PoolOptions& options);

/// Removes DIR/logs and DIR/scratch when they are empty (what is left in them is the output of
/// workers that ended without a result). A pool does it at its end unless `shared`; the Slurm
/// executor does it once the array job has ended.
void remove_empty_work_folders(const std::filesystem::path& dir);

}  // namespace impactbench::cli
