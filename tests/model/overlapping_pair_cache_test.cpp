// The pair cache must give, at every call, exactly the pairs of the all-pairs test, in the same
// order, while its boxes drift within the skin (the kept list), leave it (a new list) or change
// in number, and it must refuse what the grid refuses.
#include "lib/model/broad_phase/overlapping_pair_cache.hpp"

#include <limits>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

namespace impactbench::model {
namespace {

// A 30 x 30 lattice of squares of half-size 0.05 m, 0.1 m apart: each touches its neighbours
// within a few millimetres, as a settled pile's bodies do.
std::vector<Aabb> lattice() {
  std::vector<Aabb> boxes;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 30; ++x) {
      const Eigen::Vector3d centre(0.1 * x, 0.1 * y, 0.0);
      const Eigen::Vector3d half(0.0502, 0.0502, 0.0);
      boxes.push_back({centre - half, centre + half});
    }
  return boxes;
}

void shift(Aabb& box, const Eigen::Vector3d& by) {
  box.min += by;
  box.max += by;
}

TEST(OverlappingPairCache, EqualsAllPairsWhileBoxesDriftAndJump) {
  std::vector<Aabb> boxes = lattice();
  OverlappingPairCache cache;  // skin 0.1 of the extent 0.1004 m: about 1 cm
  std::mt19937 rng(17);
  // Drifts of up to 2 mm a call: most calls stay within the skin.
  std::uniform_real_distribution<double> drift(-0.002, 0.002);
  std::uniform_int_distribution<std::size_t> pick(0, boxes.size() - 1);
  OverlappingPairs pairs;
  constexpr int kCalls = 60;
  for (int call = 0; call < kCalls; ++call) {
    for (Aabb& box : boxes) shift(box, {drift(rng), drift(rng), 0.0});
    if (call % 10 == 9) shift(boxes[pick(rng)], {0.03, -0.02, 0.0});  // one box leaves its skin
    cache.find(boxes, pairs);
    const OverlappingPairs expected = find_overlapping_pairs_brute_force(boxes);
    ASSERT_GT(expected.size(), 1000u) << call;  // enough pairs for the comparison to mean much
    ASSERT_EQ(pairs, expected) << "call " << call;
  }
  // Both ways were taken: lists kept across calls, and lists built again.
  EXPECT_GT(cache.builds(), 5u);
  EXPECT_LT(cache.builds(), static_cast<std::size_t>(kCalls / 2));
}

TEST(OverlappingPairCache, BuildsAgainWhenTheNumberOfBoxesChanges) {
  std::vector<Aabb> boxes = lattice();
  OverlappingPairCache cache;
  OverlappingPairs pairs;
  cache.find(boxes, pairs);
  // A box dropped between four others: every old box keeps its place, so only the count tells.
  const Eigen::Vector3d centre(1.05, 1.05, 0.0);
  const Eigen::Vector3d half(0.05, 0.05, 0.0);
  boxes.push_back({centre - half, centre + half});
  cache.find(boxes, pairs);
  EXPECT_EQ(pairs, find_overlapping_pairs_brute_force(boxes));
  EXPECT_EQ(cache.builds(), 2u);
  boxes.erase(boxes.begin());
  cache.find(boxes, pairs);
  EXPECT_EQ(pairs, find_overlapping_pairs_brute_force(boxes));
  EXPECT_EQ(cache.builds(), 3u);
}

TEST(OverlappingPairCache, WithoutSkinEqualsAllPairs) {
  std::vector<Aabb> boxes = lattice();
  OverlappingPairCache cache(0.0);
  OverlappingPairs pairs;
  for (int call = 0; call < 3; ++call) {
    shift(boxes[static_cast<std::size_t>(100 * call)], {0.001, 0.0, 0.0});
    cache.find(boxes, pairs);
    EXPECT_EQ(pairs, find_overlapping_pairs_brute_force(boxes)) << call;
  }
  EXPECT_EQ(cache.builds(), 3u);
}

TEST(OverlappingPairCache, RefusesNonFiniteBoxesAndRecovers) {
  std::vector<Aabb> boxes = lattice();
  OverlappingPairCache cache;
  OverlappingPairs pairs;
  cache.find(boxes, pairs);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const double bad : {nan, inf}) {
    std::vector<Aabb> broken = boxes;
    broken[7].max.x() = bad;
    EXPECT_THROW(cache.find(broken, pairs), std::invalid_argument) << bad;
  }
  // After a refusal, boxes that moved far still get exactly their pairs.
  for (std::size_t i = 0; i < boxes.size(); i += 3) shift(boxes[i], {0.04, 0.04, 0.0});
  cache.find(boxes, pairs);
  EXPECT_EQ(pairs, find_overlapping_pairs_brute_force(boxes));
}

TEST(OverlappingPairCache, RefusesABadSkinFraction) {
  for (const double bad :
       {-0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(OverlappingPairCache{bad}, std::invalid_argument) << bad;
}

}  // namespace
}  // namespace impactbench::model
