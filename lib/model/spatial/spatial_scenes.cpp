#include "lib/model/spatial/spatial_scenes.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace impactbench::model::spatial {
namespace {

constexpr double kMinRadius = 0.045;                       // [m]
constexpr double kMaxRadius = 0.055;                       // [m]
constexpr double kJitter = 0.001;                          // [m], per coordinate
constexpr double kSpacing = 2 * kMaxRadius + 2 * kJitter;  // no overlap even at worst jitter
constexpr double kDensity = 1000.0;                        // [kg/m³]

// Uniform draws built from raw mt19937 output: std::uniform_real_distribution is not specified
// bit-for-bit across standard libraries.
double uniform(std::mt19937& rng, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(rng()) / 4294967296.0);
}

}  // namespace

SpatialSystemSpec make_sphere_pile(int count, std::uint32_t seed) {
  if (count < 1) throw std::invalid_argument("make_sphere_pile: count must be >= 1");
  std::mt19937 rng(seed);
  const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(count)) - 1e-9));
  const double width = side * kSpacing;

  SpatialSystemSpec spec;
  spec.material.friction = 0.5;
  spec.material.restitution = 0.0;
  spec.bodies.reserve(count);
  for (int k = 0; k < count; ++k) {
    const int ix = k % side, iy = (k / side) % side, layer = k / (side * side);
    BodySpec b;
    b.name = "ball" + std::to_string(k);
    b.shape = ShapeKind::kSphere;
    b.radius = uniform(rng, kMinRadius, kMaxRadius);
    b.mass = kDensity * 4.0 / 3.0 * std::numbers::pi * b.radius * b.radius * b.radius;
    b.position =
        Eigen::Vector3d((ix + 0.5) * kSpacing, (iy + 0.5) * kSpacing, (layer + 0.5) * kSpacing);
    for (int i = 0; i < 3; ++i) b.position(i) += uniform(rng, -kJitter, kJitter);
    spec.bodies.push_back(b);
  }
  spec.planes = {
      StaticPlaneSpec{"ground", Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()},
      StaticPlaneSpec{"wall_x0", Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()},
      StaticPlaneSpec{"wall_x1", Eigen::Vector3d(width, 0, 0), -Eigen::Vector3d::UnitX()},
      StaticPlaneSpec{"wall_y0", Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY()},
      StaticPlaneSpec{"wall_y1", Eigen::Vector3d(0, width, 0), -Eigen::Vector3d::UnitY()}};
  return spec;
}

}  // namespace impactbench::model::spatial
