#pragma once
// Distances between a trajectory and a reference trajectory, sampled at different times.
#include <vector>

#include <Eigen/Core>

namespace impactbench::metrics {

/// A scalar or vector signal sampled at increasing times.
struct Signal {
  std::vector<double> times;
  std::vector<Eigen::VectorXd> values;
  /// Linear interpolation at t (held constant outside the sampled range).
  Eigen::VectorXd at(double t) const;
};

struct TrajectoryError {
  double l1 = 0.0;    ///< ∫ ‖x(t) − x_ref(t)‖ dt over the common time range [unit·s]
  double linf = 0.0;  ///< max_t ‖x(t) − x_ref(t)‖
  std::vector<double> times;   ///< the trajectory's own sample times in the common range
  std::vector<double> errors;  ///< ‖x − x_ref‖ at those times
};

/// Error of `trajectory` against `reference` at the trajectory's samples (reference
/// interpolated linearly; trapezoidal rule for the L1 integral). Sizes must match.
TrajectoryError trajectory_error(const Signal& trajectory, const Signal& reference);

}  // namespace impactbench::metrics
