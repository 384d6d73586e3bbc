#pragma once
// Scene builders shared by tests, benchmarks and tools.
#include <cstdint>

#include "lib/model/spatial/spatial_system_spec.hpp"

namespace impactbench::model::spatial {

/// `count` spheres (radius 45–55 mm, mass ∝ r³ at 1000 kg/m³, at rest) on a jittered cubic lattice
/// of spacing 112 mm inside an open box: floor z = 0 ("ground") and four walls ("wall_x0",
/// "wall_x1", "wall_y0", "wall_y1") around a square footprint of ⌈∛count⌉² lattice cells. No two
/// bodies overlap; neighbouring gaps lie in [0, 24] mm, so a margin of 10 mm finds a dense contact
/// graph. The same (count, seed) gives the same scene on every platform (std::mt19937 only).
SpatialSystemSpec make_sphere_pile(int count, std::uint32_t seed);

}  // namespace impactbench::model::spatial
