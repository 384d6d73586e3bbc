#pragma once
// Helpers for code that runs with double and with the autodiff scalar (lib/model/autodiff.hpp,
// which also holds value_of): vectors of values, and derivative sizes made coherent.
#include <algorithm>
#include <type_traits>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "lib/model/autodiff.hpp"

namespace impactbench::model::spatial {

template <typename Scalar>
Eigen::Vector3d values_of(const Eigen::Matrix<Scalar, 3, 1>& v) {
  return {value_of(v.x()), value_of(v.y()), value_of(v.z())};
}

template <typename Scalar>
struct IsAutoDiff : std::false_type {};
template <typename Derivatives>
struct IsAutoDiff<Eigen::AutoDiffScalar<Derivatives>> : std::true_type {};

// Eigen's AutoDiffScalar gives constants an empty derivative vector and resizes it when it meets
// a non-empty one, but not inside unevaluated expressions (a product of two constants added to a
// variable fails an assertion, or reads out of bounds with NDEBUG). The system therefore gives
// every input entry the same derivative size on entry; only literal constants stay empty.

/// The largest derivative size among the entries of x (0 for double).
template <typename Scalar>
Eigen::Index derivative_count(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& x) {
  Eigen::Index n = 0;
  if constexpr (IsAutoDiff<Scalar>::value)
    for (Eigen::Index i = 0; i < x.size(); ++i) n = std::max(n, x(i).derivatives().size());
  return n;
}

/// x itself for double; for autodiff a copy in which every empty derivative vector is replaced by
/// zeros of size n.
template <typename Scalar>
decltype(auto) coherent(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& x, Eigen::Index n) {
  if constexpr (IsAutoDiff<Scalar>::value) {
    Eigen::Matrix<Scalar, Eigen::Dynamic, 1> y = x;
    for (Eigen::Index i = 0; i < y.size(); ++i)
      if (y(i).derivatives().size() == 0 && n > 0) y(i).derivatives().setZero(n);
    return y;
  } else {
    (void)n;
    return (x);
  }
}

}  // namespace impactbench::model::spatial
