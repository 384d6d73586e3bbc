#pragma once
// Features of a bouncing or sliding trajectory that have closed forms to compare with: apex
// heights and impact times of a bouncing body, stop time and distance of a sliding one.
#include <optional>
#include <vector>

namespace impactbench::metrics {

struct Apex {
  double t = 0.0;
  double height = 0.0;
};

/// Local maxima of the height signal y(t), each refined by the parabola through the sample and
/// its two neighbours (exact for ballistic flight), so sampled output does not bias the apex.
std::vector<Apex> apex_heights(const std::vector<double>& t, const std::vector<double>& y);

/// Times at which the vertical velocity turns from falling (< −threshold) to rising: the end of
/// each impact. For a time-stepper this is the step where the velocity jumps.
std::vector<double> impact_times(const std::vector<double>& t, const std::vector<double>& vy,
                                 double threshold = 1e-9);

struct StopPoint {
  double t = 0.0;         ///< first time |v| ≤ threshold (extrapolated at constant deceleration)
  double position = 0.0;  ///< position then
};

/// When a sliding body first comes to rest (|v| ≤ threshold after having moved).
std::optional<StopPoint> stop_point(const std::vector<double>& t, const std::vector<double>& x,
                                    const std::vector<double>& v, double threshold);

}  // namespace impactbench::metrics
