#include "lib/metrics/trajectory_error.hpp"

#include <algorithm>
#include <stdexcept>

namespace impactbench::metrics {

Eigen::VectorXd Signal::at(double t) const {
  if (times.empty()) throw std::invalid_argument("signal: no samples");
  if (t <= times.front()) return values.front();
  if (t >= times.back()) return values.back();
  const auto upper = std::upper_bound(times.begin(), times.end(), t);
  const std::size_t i = static_cast<std::size_t>(upper - times.begin());
  const double t0 = times[i - 1], t1 = times[i];
  if (t1 == t0) return values[i];
  const double s = (t - t0) / (t1 - t0);
  return (1.0 - s) * values[i - 1] + s * values[i];
}

TrajectoryError trajectory_error(const Signal& trajectory, const Signal& reference,
                                 const StateDistance& distance) {
  if (trajectory.times.size() != trajectory.values.size() ||
      reference.times.size() != reference.values.size() || trajectory.times.empty() ||
      reference.times.empty())
    throw std::invalid_argument("trajectory_error: empty signal or times/values size mismatch");
  if (trajectory.values.front().size() != reference.values.front().size())
    throw std::invalid_argument("trajectory_error: trajectory and reference have different sizes");
  const double begin = std::max(trajectory.times.front(), reference.times.front());
  const double end = std::min(trajectory.times.back(), reference.times.back());
  TrajectoryError result;
  for (std::size_t i = 0; i < trajectory.times.size(); ++i) {
    const double t = trajectory.times[i];
    if (t < begin || t > end) continue;
    const Eigen::VectorXd r = reference.at(t);
    const double e =
        distance ? distance(trajectory.values[i], r) : (trajectory.values[i] - r).norm();
    if (!result.times.empty())
      result.l1 += 0.5 * (e + result.errors.back()) * (t - result.times.back());
    result.linf = std::max(result.linf, e);
    result.times.push_back(t);
    result.errors.push_back(e);
  }
  return result;
}

}  // namespace impactbench::metrics
