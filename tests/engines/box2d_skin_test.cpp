// Box2D rounds every polygon by its skin b2_polygonRadius (0.01 m). The adapter builds each box
// and each boundary slab with its core shrunk by the skin, so that the skin's outer surface is
// the scenario's surface, and gives each box the scenario's mass and inertia (Box2D's own would
// come from the shrunk core). Touching boxes then start touching, not 2 cm into each other
// (before: the box pyramid's rows rose by 7.5 cm in the first step and gained 2.42 J), and
// heights are measured as Box2D reports them, with no correction for the skin.
#include <algorithm>
#include <cmath>
#include <string>

#include <box2d/b2_common.h>
#include <gtest/gtest.h>

#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

engines::RunResult run_box2d(const std::string& name, const scenario::ParameterOverrides& set,
                             double duration) {
  const auto s = scenario::load_scenario_by_name(name, set);
  engines::SettingsRequest request;
  request.duration = duration;
  return adapters::run_engine("box2d", s, engines::resolve_run_options("box2d", s, request));
}

// Largest rise of any body's height (column `<body>.y`) above its start over the run [m].
double largest_rise(const engines::RunResult& run) {
  const auto& names = run.trajectory.position_names;
  const auto& first = run.trajectory.samples.front().q;
  double rise = 0.0;
  for (const auto& sample : run.trajectory.samples)
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k].size() > 2 && names[k].compare(names[k].size() - 2, 2, ".y") == 0)
        rise = std::max(
            rise, sample.q[static_cast<Eigen::Index>(k)] - first[static_cast<Eigen::Index>(k)]);
  return rise;
}

TEST(Box2dSkin, ARestingBoxStaysWithinOneSlopOfItsExactHeight) {
  // One box (rows = 1) of side 0.2 m on the ground. Box2D corrects a penetration only where it
  // exceeds b2_linearSlop, so a box that starts touching ends between its exact height 0.1 m and
  // one slop (0.005 m) below it, never above (1e-6 m: float rounding of 0.1 m). Before, its
  // skin and the ground's overlapped by 2 cm and it was pushed up to 0.115 m.
  const auto run = run_box2d("box_pyramid", {{"rows", 1.0}}, 1.0);
  const double y = run.trajectory.samples.back().q[1];
  EXPECT_LE(y, 0.1 + 1e-6);
  EXPECT_GE(y, 0.1 - b2_linearSlop);
  EXPECT_LE(largest_rise(run), 1e-6);  // nothing pushes it up: it starts touching, not inside
}

TEST(Box2dSkin, APyramidStartsTouchingAndDoesNotRise) {
  // Four rows of touching boxes: no outer surface starts inside another, so no position
  // correction lifts a box, and a resting pyramid gains no energy. Bounds: float rounding of
  // the positions (1e-6 m) and of the energy (1e-5 J on 10 J).
  const auto run = run_box2d("box_pyramid", {{"rows", 4.0}}, 0.2);
  EXPECT_LE(largest_rise(run), 1e-6);
  double most_energy = run.first_energy;
  for (const auto& sample : run.trajectory.samples)
    most_energy = std::max(most_energy, sample.energy);
  EXPECT_LE(most_energy - run.first_energy, 1e-5);
}

TEST(Box2dSkin, ABoxThinnerThanTwoSkinsHasAThinnerSkin) {
  // A 1.5 cm box cannot keep a 1 cm skin inside it; its skin is a quarter of its side, and it
  // too rests between its exact height 0.0075 m and one slop below.
  const auto run = run_box2d("box_pyramid", {{"rows", 1.0}, {"size", 0.015}}, 0.5);
  const double y = run.trajectory.samples.back().q[1];
  EXPECT_LE(y, 0.0075 + 1e-6);
  EXPECT_GE(y, 0.0075 - b2_linearSlop);
}

}  // namespace
}  // namespace impactbench
