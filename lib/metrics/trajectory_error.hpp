#pragma once
// Distances between a trajectory and a reference trajectory, sampled at different times.
#include <functional>
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

/// The distance between a state and the reference state at the same time.
using StateDistance = std::function<double(const Eigen::VectorXd&, const Eigen::VectorXd&)>;

/// Error of `trajectory` against `reference` at the trajectory's samples (reference
/// interpolated linearly; trapezoidal rule for the L1 integral). Sizes must match. The
/// distance is ‖x − x_ref‖ unless one is given.
TrajectoryError trajectory_error(const Signal& trajectory, const Signal& reference,
                                 const StateDistance& distance = {});

}  // namespace impactbench::metrics
