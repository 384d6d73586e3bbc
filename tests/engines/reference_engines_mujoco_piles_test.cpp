// MuJoCo runs every pile size the other engines run. MuJoCo 2.2.2 allocates its constraint
// arrays densely, njmax² and njmax · nv cells in one buffer of at most 2^31 bytes; the adapter
// gave every model nconmax = 50 + 12 n and njmax = 6 nconmax, which passes that limit from
// about 150 spheres (200 spheres: njmax 14,700, 3.0 GB), so `run sphere_pile --set count=200`
// failed with "could not create mjData".
#include <cstdint>

#include <gtest/gtest.h>

#include "tools/engines/fixed_step/scene_from_scenario.hpp"
#include "tools/engines/mujoco/mujoco_sizes.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::adapters {
namespace {

constexpr double kTwoGiB = 2147483648.0;

struct Pile {
  const char* scenario;
  double count;
};

class MujocoPileSizes : public ::testing::TestWithParam<Pile> {};

TEST_P(MujocoPileSizes, FitMuJoCosBufferWithAsManyContactsAsItHolds) {
  const auto s =
      scenario::load_scenario_by_name(GetParam().scenario, {{"count", GetParam().count}});
  const ReferenceScene scene = make_reference_scene(s, s.duration, 1e-3);
  const auto n = static_cast<std::int64_t>(scene.bodies.size());
  const std::int64_t nv = n * (scene.planar ? 3 : 6);
  for (const bool elliptic : {true, false}) {
    const MujocoSizes sizes = mujoco_sizes(scene, elliptic);
    EXPECT_LT(static_cast<double>(sizes.buffer_bytes), kTwoGiB);
    EXPECT_EQ(sizes.njmax, rows_per_contact(elliptic) * sizes.nconmax);
    // As many contacts as the shapes can have, or else the most the buffer holds: one more
    // contact's rows would pass the limit.
    if (sizes.nconmax < sizes.geometric) {
      const std::int64_t more = sizes.njmax + rows_per_contact(elliptic);
      EXPECT_GT(static_cast<double>(more * (12 * more + 24 * nv)), 0.9 * kTwoGiB);
    }
    // The old sizing's buffer, for the record: past the limit at every one of these sizes.
    const std::int64_t old_njmax = 6 * (50 + 12 * n);
    EXPECT_GT(static_cast<double>(old_njmax * (12 * old_njmax + 24 * nv)), kTwoGiB);
  }
}

INSTANTIATE_TEST_SUITE_P(Piles, MujocoPileSizes,
                         ::testing::Values(Pile{"sphere_pile", 200}, Pile{"sphere_pile", 400},
                                           Pile{"sphere_pile", 600}, Pile{"sphere_pile", 1000},
                                           Pile{"disk_pile", 1000}));

TEST(MujocoPiles, TwoHundredSpheresRun) {
  // The model is built and stepped (two steps: the model and its mjData are what failed).
  const auto s = scenario::load_scenario_by_name("sphere_pile", {{"count", 200}});
  engines::SettingsRequest request;
  request.duration = 0.002;
  const auto run =
      adapters::run_engine("mujoco", s, engines::resolve_run_options("mujoco", s, request));
  EXPECT_EQ(run.step_count, 2);
  EXPECT_EQ(run.trajectory.position_names.size(), 7u * 200u);
}

}  // namespace
}  // namespace impactbench::adapters
