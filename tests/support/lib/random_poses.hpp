#pragma once
// Random poses for the spatial rigid-body tests: unit quaternions and bounded vectors.
#include <random>

#include <Eigen/Core>

namespace impactbench::test_support {

/// A uniformly distributed unit quaternion, as (w, x, y, z).
inline Eigen::Vector4d random_unit_quaternion(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Vector4d q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized();
}

inline Eigen::Vector3d random_vector(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

}  // namespace impactbench::test_support
