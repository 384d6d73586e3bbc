#include "lib/metrics/run_figures.hpp"

#include <limits>

namespace impactbench::metrics {

std::vector<std::pair<std::string, double>> run_figures(const engines::RunResult& run) {
  return {{"engine_cpu_seconds", run.engine_cpu_seconds},
          {"record_cpu_seconds", run.record_cpu_seconds},
          {"wall_seconds", run.wall_seconds},
          {"steps", static_cast<double>(run.step_count)},
          {"unconverged_steps", run.unconverged_steps ? static_cast<double>(*run.unconverged_steps)
                                                      : std::numeric_limits<double>::quiet_NaN()},
          {"mean_contacts", run.mean_contacts}};
}

}  // namespace impactbench::metrics
