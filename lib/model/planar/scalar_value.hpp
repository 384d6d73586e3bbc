#pragma once
// The plain double value of a model scalar: the scalar itself for double, the value part of an
// Eigen::AutoDiffScalar. Geometry decisions (active feature, broad phase) use these values only,
// so that they are constant in a neighbourhood and derivatives flow through the formulas.
#include <type_traits>

namespace impactbench::model::planar {

template <typename Scalar>
double scalar_value(const Scalar& s) {
  if constexpr (std::is_arithmetic_v<Scalar>) {
    return static_cast<double>(s);
  } else {
    return scalar_value(s.value());
  }
}

}  // namespace impactbench::model::planar
