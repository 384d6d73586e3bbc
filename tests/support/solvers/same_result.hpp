#pragma once
// Comparisons of two SolverResults for the tests that solve one problem two ways (into a kept
// result and a new one, timed and untimed) and expect the same answer to the bit.
#include <cmath>
#include <cstddef>
#include <cstring>

#include <gtest/gtest.h>

#include "solvers/common/capacity_vector.hpp"
#include "solvers/common/solver_types.hpp"

namespace impactbench::solvers {

/// The same values to the bit (so +0 and −0 differ, and a NaN matches its own bits). An empty
/// vector may hold no storage (a null data()), and memcmp's pointers must not be null even for
/// zero bytes, so empty vectors are compared by size alone.
inline bool same_bits(VectorView a, VectorView b) {
  if (a.size() != b.size()) return false;
  if (a.size() == 0) return true;
  return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

/// Equal, or both NaN.
inline bool same_number(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

/// The same answer, status, iterations, residuals and message; the time is not compared.
inline void expect_same_result(const SolverResult& a, const SolverResult& b) {
  EXPECT_TRUE(same_bits(a.solution, b.solution));
  EXPECT_TRUE(same_bits(a.velocity, b.velocity));
  EXPECT_TRUE(same_bits(a.factored_velocity, b.factored_velocity));
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_TRUE(same_number(a.residual, b.residual)) << a.residual << " " << b.residual;
  EXPECT_TRUE(same_number(a.faceted_residual, b.faceted_residual));
  EXPECT_EQ(a.message, b.message);
}

/// A solve with the driver's timer off: the timed solve's answer, and NaN seconds.
inline void expect_untimed_like_timed(const SolverResult& untimed, const SolverResult& timed) {
  EXPECT_GE(timed.seconds, 0.0);
  EXPECT_TRUE(std::isnan(untimed.seconds)) << untimed.seconds;
  expect_same_result(untimed, timed);
}

}  // namespace impactbench::solvers
