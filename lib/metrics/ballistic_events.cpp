#include "lib/metrics/ballistic_events.hpp"

#include <cfloat>
#include <cmath>
#include <stdexcept>

namespace impactbench::metrics {
namespace {

void check_sizes(std::size_t a, std::size_t b) {
  if (a != b) throw std::invalid_argument("metrics: times and values differ in length");
}

}  // namespace

std::vector<Apex> apex_heights(const std::vector<double>& t, const std::vector<double>& y) {
  check_sizes(t.size(), y.size());
  std::vector<Apex> apexes;
  for (std::size_t i = 1; i + 1 < y.size(); ++i) {
    if (!(y[i] > y[i - 1] && y[i] >= y[i + 1])) continue;
    // Parabola through (t_{i-1}, y_{i-1}), (t_i, y_i), (t_{i+1}, y_{i+1}).
    const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
    const double d0 = (y[i] - y[i - 1]) / h0, d1 = (y[i + 1] - y[i]) / h1;
    const double curvature = (d1 - d0) / (h0 + h1);  // half the second derivative
    Apex apex{t[i], y[i]};
    if (curvature < 0.0) {
      // y(s) = y_i + b (s − t_i) + c (s − t_i)², b from the centred slope.
      const double b = d0 + curvature * h0;
      const double shift = -b / (2.0 * curvature);
      if (std::abs(shift) <= std::max(h0, h1)) {
        apex.t = t[i] + shift;
        apex.height = y[i] + b * shift + curvature * shift * shift;
      }
    }
    apexes.push_back(apex);
  }
  return apexes;
}

std::vector<double> impact_times(const std::vector<double>& t, const std::vector<double>& vy,
                                 double threshold) {
  check_sizes(t.size(), vy.size());
  std::vector<double> impacts;
  for (std::size_t i = 1; i < vy.size(); ++i)
    if (vy[i - 1] < -threshold && vy[i] > threshold) impacts.push_back(t[i]);
  return impacts;
}

std::optional<StopPoint> stop_point(const std::vector<double>& t, const std::vector<double>& x,
                                    const std::vector<double>& v, double threshold) {
  check_sizes(t.size(), x.size());
  check_sizes(t.size(), v.size());
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (std::abs(v[i]) > threshold || std::abs(v[i - 1]) <= threshold) continue;
    const double a = std::abs(v[i - 1]);
    // Constant deceleration measured over the previous interval locates the stop exactly for
    // Coulomb sliding, whose speed falls linearly; the last sample is already clamped at rest.
    if (i >= 2) {
      const double decel = (std::abs(v[i - 2]) - a) / (t[i - 1] - t[i - 2]);
      const double tau = decel > 0.0 ? a / decel : -1.0;
      // The stop at the last sample itself (an engine's sample at its stop event) may come out
      // past it by round-off of the times' differences.
      const double round_off = 16.0 * DBL_EPSILON * std::abs(t[i]);
      if (tau >= 0.0 && tau <= t[i] - t[i - 1] + round_off)
        return StopPoint{t[i - 1] + tau, x[i - 1] + 0.5 * v[i - 1] * tau};
    }
    const double b = std::abs(v[i]);
    const double s = (a - threshold) / (a - b);
    return StopPoint{t[i - 1] + s * (t[i] - t[i - 1]), x[i - 1] + s * (x[i] - x[i - 1])};
  }
  return std::nullopt;
}

}  // namespace impactbench::metrics
