#pragma once
// The plain double behind a scalar that may be an automatic-differentiation type. Geometry
// decisions (which face is closest, is a gap below the margin) are made on these values only, so
// the same code runs with double and with Eigen::AutoDiffScalar.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace impactbench::model::spatial {

inline double value_of(double x) {
  return x;
}

template <typename Derivatives>
double value_of(const Eigen::AutoDiffScalar<Derivatives>& x) {
  return x.value();
}

template <typename Scalar>
Eigen::Vector3d values_of(const Eigen::Matrix<Scalar, 3, 1>& v) {
  return {value_of(v.x()), value_of(v.y()), value_of(v.z())};
}

}  // namespace impactbench::model::spatial
