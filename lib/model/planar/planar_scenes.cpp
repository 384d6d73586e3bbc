#include "lib/model/planar/planar_scenes.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace impactbench::model::planar {

PlanarScene make_disk_pile(int count, unsigned seed) {
  if (count < 1) throw std::invalid_argument("make_disk_pile: count must be >= 1");
  constexpr double kPitch = 0.1;
  constexpr double kDensity = 100.0;  // [kg/m²]
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> radius(0.045, 0.055);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);

  PlanarScene scene;
  scene.bodies.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    BodySpec disk;
    disk.name = "disk" + std::to_string(i);
    disk.shape = ShapeKind::kDisk;
    disk.radius = radius(rng);
    disk.mass = kDensity * std::numbers::pi * disk.radius * disk.radius;
    disk.position = {(i % columns + 0.5) * kPitch + jitter(rng),
                     (i / columns + 0.5) * kPitch + jitter(rng), 0.0};
    scene.bodies.push_back(std::move(disk));
  }
  const double width = columns * kPitch;
  scene.planes = {
      StaticPlaneSpec{"ground", Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY()},
      StaticPlaneSpec{"left_wall", Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()},
      StaticPlaneSpec{"right_wall", Eigen::Vector3d(width, 0.0, 0.0), -Eigen::Vector3d::UnitX()}};
  return scene;
}

PlanarScene make_box_pyramid(int rows) {
  if (rows < 1) throw std::invalid_argument("make_box_pyramid: rows must be >= 1");
  constexpr double kSize = 0.5;
  constexpr double kPitch = 1.05 * kSize;
  PlanarScene scene;
  for (int row = 0; row < rows; ++row) {
    const int in_row = rows - row;
    const double first_x = -0.5 * (in_row - 1) * kPitch;
    for (int column = 0; column < in_row; ++column) {
      BodySpec box;
      box.name = "box_" + std::to_string(row) + "_" + std::to_string(column);
      box.shape = ShapeKind::kBox;
      box.size = {kSize, kSize, 0.0};
      box.mass = 1.0;
      box.position = {first_x + column * kPitch, (row + 0.5) * kSize, 0.0};
      scene.bodies.push_back(std::move(box));
    }
  }
  scene.planes = {StaticPlaneSpec{"ground", Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY()}};
  return scene;
}

}  // namespace impactbench::model::planar
