#pragma once
#include <vector>

namespace impactbench::metrics {

struct EnergyDrift {
  double relative_change = 0.0;  ///< (E_end − E_0) / |E_0| (E_0 = 0: absolute)
  double max_rise = 0.0;         ///< largest increase of E across one sample interval [J]
};

/// Drift of the energy signal; a passive system without input work must have max_rise ≈ 0.
EnergyDrift energy_drift(const std::vector<double>& energy);

}  // namespace impactbench::metrics
