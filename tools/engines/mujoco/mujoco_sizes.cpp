#include "tools/engines/mujoco/mujoco_sizes.hpp"

#include <algorithm>
#include <cmath>

namespace impactbench::adapters {
namespace {

// Below 2^31 bytes with room for mjData's other arrays, which grow with nv and nconmax only.
constexpr double kBufferLimit = 0.9 * 2147483648.0;

std::int64_t buffer_bytes(std::int64_t njmax, std::int64_t nv) {
  return njmax * (12 * njmax + 24 * nv);
}

}  // namespace

int rows_per_contact(bool elliptic) {
  return elliptic ? 3 : 4;
}

MujocoSizes mujoco_sizes(const ReferenceScene& scene, bool elliptic) {
  const auto nb = static_cast<std::int64_t>(scene.bodies.size());
  const std::int64_t dims = scene.planar ? 2 : 3;
  // A body touches at most one boundary per direction at once (a corner of the box).
  const std::int64_t boundaries =
      std::min<std::int64_t>(static_cast<std::int64_t>(scene.planes.size()), dims);
  std::int64_t bound = 50;  // room for the few contacts of the smallest scenes
  for (const auto& body : scene.bodies) {
    const bool round =
        body.shape == model::ShapeKind::kDisk || body.shape == model::ShapeKind::kSphere;
    bound += round ? (scene.planar ? 3 : 6) + boundaries
                   : 4 * std::min<std::int64_t>(nb - 1, 12) + 4 * boundaries;
  }
  const std::int64_t nv = nb * (scene.planar ? 3 : 6);
  const int rows = rows_per_contact(elliptic);
  // The largest njmax whose buffer fits: 12 n² + 24 nv n = limit.
  const double fit = (-24.0 * nv + std::sqrt(576.0 * nv * nv + 48.0 * kBufferLimit)) / 24.0;
  const auto fitting_contacts = static_cast<std::int64_t>(fit) / rows;
  MujocoSizes sizes;
  sizes.geometric = bound;
  sizes.nconmax = static_cast<int>(std::min(bound, fitting_contacts));
  sizes.njmax = rows * sizes.nconmax;
  sizes.buffer_bytes = buffer_bytes(sizes.njmax, nv);
  return sizes;
}

}  // namespace impactbench::adapters
