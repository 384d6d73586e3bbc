#include "lib/metrics/energy_drift.hpp"

#include <algorithm>
#include <cmath>

namespace impactbench::metrics {

EnergyDrift energy_drift(const std::vector<double>& energy) {
  EnergyDrift drift;
  if (energy.size() < 2) return drift;
  const double scale = energy.front() != 0.0 ? std::abs(energy.front()) : 1.0;
  drift.relative_change = (energy.back() - energy.front()) / scale;
  for (std::size_t i = 1; i < energy.size(); ++i)
    drift.max_rise = std::max(drift.max_rise, energy[i] - energy[i - 1]);
  return drift;
}

}  // namespace impactbench::metrics
