#pragma once
// A progress line on stderr for a long run: "run: t = 3.2 of 10 s (32%), 12 s elapsed",
// rewritten in place. By default it appears only after a few seconds of wall-clock time, so
// short runs print nothing; it is refreshed at most a few times a second (the clock is read on
// every call: tens of nanoseconds against a step of microseconds).
#include <chrono>
#include <string>

namespace impactbench::cli {

class ProgressLine {
 public:
  /// `label` starts the line; `duration` [s] is the simulated time the run reaches. With
  /// `from_start` the line is shown from the first update (asked for with --progress).
  ProgressLine(std::string label, double duration, bool from_start = false);
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  /// Ends the line (a newline) if one was shown.
  ~ProgressLine();

  /// The run has reached simulated time t.
  void update(double t);
  bool shown() const { return shown_; }

  /// Whether `run` shows progress by default: only when stderr is a terminal.
  static bool stderr_is_terminal();

 private:
  using Clock = std::chrono::steady_clock;
  std::string label_;
  double duration_;
  Clock::time_point start_;
  Clock::time_point next_print_;
  bool shown_ = false;
};

}  // namespace impactbench::cli
