#include "lib/metrics/run_signal.hpp"

namespace impactbench::metrics {

Signal position_signal(const engines::RunResult& run) {
  Signal signal;
  signal.times.reserve(run.trajectory.samples.size());
  signal.values.reserve(run.trajectory.samples.size());
  for (const auto& sample : run.trajectory.samples) {
    signal.times.push_back(sample.t);
    signal.values.push_back(sample.q);
  }
  return signal;
}

}  // namespace impactbench::metrics
