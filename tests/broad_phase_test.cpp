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

TEST(BroadPhase, GridEqualsBruteForcePlanar) {
  const auto boxes = random_boxes(1000, 2, 7);
  const auto expected = find_overlapping_pairs_brute_force(boxes);
  ASSERT_GT(expected.size(), 500u);  // the pile must actually be in contact
  EXPECT_EQ(find_overlapping_pairs(boxes), expected);
}

TEST(BroadPhase, GridEqualsBruteForceSpatial) {
  const auto boxes = random_boxes(1000, 3, 11);
  const auto expected = find_overlapping_pairs_brute_force(boxes);
  ASSERT_GT(expected.size(), 500u);
  EXPECT_EQ(find_overlapping_pairs(boxes), expected);
}

TEST(BroadPhase, RejectsNonFiniteBoxes) {
  auto boxes = random_boxes(100, 3, 3);
  boxes[5].max.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(find_overlapping_pairs(boxes), std::invalid_argument);
}

}  // namespace
}  // namespace impactbench::model
