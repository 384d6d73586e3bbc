#include "lib/metrics/penetration.hpp"

#include <algorithm>
#include <vector>

namespace impactbench::metrics {

double max_penetration(const model::LagrangianSystem<double>& system,
                       const output::Trajectory& trajectory) {
  double deepest = 0.0;
  std::vector<model::Contact<double>> contacts;
  for (const auto& sample : trajectory.samples) {
    // Margin 0: the contacts that touch or penetrate.
    system.find_contacts(sample.q, sample.v, 0.0, contacts);
    for (const auto& c : contacts) deepest = std::max(deepest, -c.gap);
  }
  return deepest;
}

}  // namespace impactbench::metrics
