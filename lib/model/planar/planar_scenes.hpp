#pragma once
// Scene builders shared by benchmarks, tests and scenarios: plain specs, no system.
#include <vector>

#include "lib/model/body_spec.hpp"

namespace impactbench::model::planar {

struct PlanarScene {
  std::vector<BodySpec> bodies;
  std::vector<StaticPlaneSpec> planes;
};

/// `count` disks (radius 4.5–5.5 cm, areal density 100 kg/m²) on a jittered square grid of pitch
/// 10 cm, so that neighbours overlap or nearly touch, inside a box made of a floor (y = 0) and
/// two walls (x = 0 and x = width). Deterministic for a given seed. Names disk0, disk1, ...
PlanarScene make_disk_pile(int count, unsigned seed);

/// A pyramid of 0.5 m x 0.5 m boxes of 1 kg: `rows` boxes on the floor with 2.5 cm side gaps,
/// each upper box centred on the gap between the two below and resting on them with zero gap.
/// Names box_<row>_<column>, row 0 on the floor (y = 0).
PlanarScene make_box_pyramid(int rows);

}  // namespace impactbench::model::planar
