#pragma once
// The progress line of a sweep on stderr: "sweep: 40 of 200 points, 1 failed, 3.2 points/s,
// ETA 50 s", rewritten in place at most a few times a second; ended by a newline.
#include <chrono>
#include <cstddef>

namespace impactbench::cli {

class SweepProgress {
 public:
  /// `shown`: whether to print at all (a terminal, or --progress).
  SweepProgress(std::size_t total, bool shown);
  SweepProgress(const SweepProgress&) = delete;
  SweepProgress& operator=(const SweepProgress&) = delete;
  ~SweepProgress();

  /// `done` points finished, `failed` of them failed, timed out or were lost.
  void update(std::size_t done, std::size_t failed, bool force = false);

 private:
  using Clock = std::chrono::steady_clock;
  std::size_t total_;
  bool shown_;
  bool printed_ = false;
  Clock::time_point start_;
  Clock::time_point next_;
};

}  // namespace impactbench::cli
