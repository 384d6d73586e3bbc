#include "tools/cli/solve_monitor.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "lib/engines/run_timer.hpp"
#include "lib/output/number_text.hpp"

namespace impactbench::cli {

SolveMonitor::SolveMonitor(std::optional<double> time_limit_seconds, bool show_progress)
    : time_limit_(time_limit_seconds),
      show_progress_(show_progress),
      start_(engines::process_cpu_seconds()) {}

void SolveMonitor::restart() {
  start_ = engines::process_cpu_seconds();
}

double SolveMonitor::cpu_seconds() const {
  return engines::process_cpu_seconds() - start_;
}

bool SolveMonitor::operator()(int iteration, double residual) {
  const double elapsed = cpu_seconds();
  if (show_progress_ && elapsed >= next_report_) {
    const std::string residual_text =
        std::isnan(residual) ? std::string("n/a") : output::number_text(residual);
    std::fprintf(stderr, "solve: iteration %d, residual %s, %.0f s CPU\n", iteration,
                 residual_text.c_str(), elapsed);
    next_report_ = elapsed + 1.0;
  }
  if (time_limit_ && elapsed >= *time_limit_) {
    limit_reached_ = true;
    return false;
  }
  return true;
}

}  // namespace impactbench::cli
