#pragma once
// Whether every value is finite, at about the cost of a vectorised sum: a NaN or an infinity
// makes the sum non-finite, so a finite sum settles it, and only a sum that is not finite (such a
// value, or an overflow of finite ones) is looked at value by value. For the checks that run on
// every solve or step.
#include <cmath>

#include <Eigen/Core>

namespace impactbench::solvers {

template <typename Derived>
bool all_finite(const Eigen::DenseBase<Derived>& values) {
  return std::isfinite(values.sum()) || values.allFinite();
}

/// The n values from `values`.
inline bool all_finite(const double* values, Eigen::Index n) {
  return all_finite(Eigen::Map<const Eigen::VectorXd>(values, n));
}

}  // namespace impactbench::solvers
