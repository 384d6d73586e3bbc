#include "lib/model/broad_phase/uniform_grid.hpp"

#include <random>

#include <gtest/gtest.h>

namespace impactbench::model {
namespace {

// Random boxes of similar size packed densely enough that most have several neighbours.
std::vector<Aabb> random_boxes(int count, int dims, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> centre(0.0, dims == 2 ? 3.0 : 1.2);
  std::uniform_real_distribution<double> half(0.02, 0.06);
  std::vector<Aabb> boxes(count);
  for (Aabb& b : boxes) {
    Eigen::Vector3d c(centre(rng), centre(rng), dims == 2 ? 0.0 : centre(rng));
    Eigen::Vector3d h = Eigen::Vector3d::Constant(half(rng));
    if (dims == 2) h.z() = 0.0;
    b.min = c - h;
    b.max = c + h;
  }
  return boxes;
}

// The grid finds exactly the pairs the brute force finds, and there are enough of them for the
// comparison to mean something.
void expect_grid_equals_brute_force(const std::vector<Aabb>& boxes, std::size_t at_least) {
  const auto expected = find_overlapping_pairs_brute_force(boxes);
  ASSERT_GT(expected.size(), at_least);
  EXPECT_EQ(find_overlapping_pairs(boxes), expected);
}

TEST(BroadPhase, GridEqualsBruteForcePlanar) {
  expect_grid_equals_brute_force(random_boxes(1000, 2, 7), 500u);  // a pile in contact
}

TEST(BroadPhase, GridEqualsBruteForceSpatial) {
  expect_grid_equals_brute_force(random_boxes(1000, 3, 11), 500u);
}

TEST(BroadPhase, GridEqualsBruteForceWhenCellsAreHashed) {
  // Two dense clusters 1 km apart: the grid spans far more cells than boxes, so cells are
  // hashed into buckets (distinct cells may share one).
  auto boxes = random_boxes(600, 3, 5);
  for (std::size_t i = 0; i < boxes.size(); i += 2) {
    boxes[i].min.x() += 1000.0;
    boxes[i].max.x() += 1000.0;
  }
  expect_grid_equals_brute_force(boxes, 100u);
}

TEST(BroadPhase, GridEqualsBruteForceForTouchingBoxesAndOneLargeOne) {
  // Unit squares on a lattice, each touching its neighbours exactly (touching counts as
  // overlapping), several stacked in one cell, and one box four times as wide: the cells take
  // its size, so each holds many boxes and the scans cross whole rows.
  std::vector<Aabb> boxes;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 30; ++x)
      for (int copy = 0; copy < (x % 7 == 0 ? 2 : 1); ++copy)
        boxes.push_back({Eigen::Vector3d(x, y, 0.0), Eigen::Vector3d(x + 1.0, y + 1.0, 0.0)});
  expect_grid_equals_brute_force(boxes, 2000u);
  // First in the list, so that its 30-odd pairs share one first index.
  boxes.insert(boxes.begin(), {Eigen::Vector3d(10.5, 5.5, 0.0), Eigen::Vector3d(14.5, 9.5, 0.0)});
  expect_grid_equals_brute_force(boxes, 2000u);
}

TEST(BroadPhase, GridEqualsBruteForceBeyondCountableCells) {
  // Clusters 1e20 m apart span more cells than 64 bits count: all pairs are tested instead.
  auto boxes = random_boxes(200, 3, 9);
  for (std::size_t i = 0; i < boxes.size(); i += 2) {
    boxes[i].min += Eigen::Vector3d::Constant(1e20);
    boxes[i].max += Eigen::Vector3d::Constant(1e20);
  }
  expect_grid_equals_brute_force(boxes, 10u);
}

TEST(BroadPhase, RejectsNonFiniteBoxes) {
  auto boxes = random_boxes(100, 3, 3);
  boxes[5].max.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(find_overlapping_pairs(boxes), std::invalid_argument);
}

}  // namespace
}  // namespace impactbench::model
