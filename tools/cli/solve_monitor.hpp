#pragma once
// What `impactbench solve` watches while a solver iterates: the time limit (process CPU time
// since the solve started) and a progress line on stderr once a second, shown after the first
// two seconds when stderr is a terminal or when asked (--progress).
#include <optional>

namespace impactbench::cli {

class SolveMonitor {
 public:
  SolveMonitor(std::optional<double> time_limit_seconds, bool show_progress);
  /// The SolverOptions::monitor: false once the time limit is reached.
  bool operator()(int iteration, double residual);
  bool time_limit_reached() const { return limit_reached_; }
  double cpu_seconds() const;  ///< process CPU time since construction or restart()
  void restart();

 private:
  std::optional<double> time_limit_;
  bool show_progress_;
  double start_ = 0.0;
  double next_report_ = 2.0;  ///< CPU seconds after start of the next progress line
  bool limit_reached_ = false;
};

}  // namespace impactbench::cli
