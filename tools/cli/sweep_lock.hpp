#pragma once
// The lock of a sweep's output folder, flock(2) on DIR/lock, held for the object's life (the
// kernel drops it when the process ends, however it ends). A sweep takes it exclusively; the
// shards of a Slurm array, which write disjoint points, share it.
#include <filesystem>

namespace impactbench::cli {

class SweepLock {
 public:
  /// Throws CliError (exit 1) naming the folder when another sweep holds the lock.
  SweepLock(const std::filesystem::path& dir, bool shared);
  SweepLock(const SweepLock&) = delete;
  SweepLock& operator=(const SweepLock&) = delete;
  ~SweepLock();

 private:
  int fd_ = -1;
};

}  // namespace impactbench::cli
