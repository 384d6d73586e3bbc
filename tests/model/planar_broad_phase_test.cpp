// The uniform-grid broad phase with real shapes must find exactly the contacts of the all-pairs
// narrow phase, on a random pile of 1,000 disks and on a box pyramid.
#include <gtest/gtest.h>

#include "lib/model/planar/planar_scenes.hpp"
#include "lib/model/planar/planar_system.hpp"

namespace impactbench::model::planar {
namespace {

using System = PlanarRigidBodySystemd;

void expect_grid_equals_all_pairs(const PlanarScene& scene, double margin, std::size_t at_least) {
  System system(scene.bodies, scene.planes, 9.81, {0.5, 0.0});
  const Eigen::VectorXd q = system.initial_positions();
  const Eigen::VectorXd v = Eigen::VectorXd::Random(system.num_velocities());
  std::vector<Contact<double>> grid;
  std::vector<Contact<double>> all_pairs;
  system.find_contacts(q, v, margin, grid);
  system.set_broad_phase(BroadPhase::kAllPairs);
  system.find_contacts(q, v, margin, all_pairs);
  ASSERT_EQ(grid.size(), all_pairs.size());
  EXPECT_GE(grid.size(), at_least);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_EQ(grid[i].key, all_pairs[i].key);
    EXPECT_EQ(grid[i].name, all_pairs[i].name);
    EXPECT_EQ(grid[i].gap, all_pairs[i].gap);
    EXPECT_EQ(grid[i].normal_drift, all_pairs[i].normal_drift);
    EXPECT_LE(grid[i].gap, margin);
  }
}

TEST(PlanarBroadPhase, DiskPileContactsEqualAllPairs) {
  const PlanarScene pile = make_disk_pile(1000, 11);
  ASSERT_EQ(pile.bodies.size(), 1000u);
  // A 32 x 32 grid of ~touching disks has ~1,900 neighbour pairs plus the wall contacts.
  expect_grid_equals_all_pairs(pile, 0.01, 1000);
}

TEST(PlanarBroadPhase, MovingPileContactsEqualAllPairsAtEveryCall) {
  // The grid's pairs are kept across calls while the bodies stay within a skin: a pile moved
  // call after call, slowly (the kept pairs) and then fast (new pairs), must still find the
  // all-pairs contacts at every call.
  const PlanarScene pile = make_disk_pile(1000, 11);
  System grid_system(pile.bodies, pile.planes, 9.81, {0.5, 0.0});
  System all_pairs_system(pile.bodies, pile.planes, 9.81, {0.5, 0.0});
  all_pairs_system.set_broad_phase(BroadPhase::kAllPairs);
  Eigen::VectorXd q = grid_system.initial_positions();
  const Eigen::VectorXd v = Eigen::VectorXd::Random(grid_system.num_velocities());
  std::vector<Contact<double>> grid;
  std::vector<Contact<double>> all_pairs;
  for (int call = 0; call < 20; ++call) {
    q += (call < 10 ? 1e-4 : 5e-3) * v;
    grid_system.find_contacts(q, v, 0.01, grid);
    all_pairs_system.find_contacts(q, v, 0.01, all_pairs);
    ASSERT_EQ(grid.size(), all_pairs.size()) << call;
    EXPECT_GE(grid.size(), 1000u) << call;
    for (std::size_t i = 0; i < grid.size(); ++i) {
      ASSERT_EQ(grid[i].key, all_pairs[i].key) << call;
      ASSERT_EQ(grid[i].gap, all_pairs[i].gap) << call;
    }
  }
}

TEST(PlanarBroadPhase, BoxPyramidContactsEqualAllPairs) {
  const PlanarScene pyramid = make_box_pyramid(12);
  ASSERT_EQ(pyramid.bodies.size(), 78u);
  // 12 floor boxes x 2 corners, and every upper box rests on two boxes with 2 points each.
  expect_grid_equals_all_pairs(pyramid, 1e-9, 24 + 4 * 66);
}

TEST(PlanarBroadPhase, PyramidRestsWithZeroGaps) {
  const PlanarScene pyramid = make_box_pyramid(4);
  System system(pyramid.bodies, pyramid.planes, 9.81, {});
  std::vector<Contact<double>> contacts;
  system.find_contacts(system.initial_positions(), Eigen::VectorXd::Zero(system.num_velocities()),
                       1e-9, contacts);
  for (const auto& c : contacts) {
    EXPECT_NEAR(c.gap, 0.0, 1e-12) << c.name;
    EXPECT_NEAR(c.normal.y(), 1.0, 1e-12) << c.name;
  }
  // 4 floor boxes x 2 corners + 6 upper boxes x 2 resting points on each of 2 supports.
  EXPECT_EQ(contacts.size(), 8u + 6u * 4u);
}

}  // namespace
}  // namespace impactbench::model::planar
