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

// A lattice of squares (30 x 30) or cubes (10 x 10 x 10) of half-size 0.0502 m, 0.1 m apart:
// each touches its neighbours within a few millimetres, as a settled pile's bodies do.
std::vector<Aabb> lattice(int dims = 2) {
  const int n = dims == 2 ? 30 : 10;
  const Eigen::Vector3d half(0.0502, 0.0502, dims == 2 ? 0.0 : 0.0502);
  std::vector<Aabb> boxes;
  for (int z = 0; z < (dims == 2 ? 1 : n); ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Eigen::Vector3d centre(0.1 * x, 0.1 * y, 0.1 * z);
        boxes.push_back({centre - half, centre + half});
      }
  return boxes;
}

void shift(Aabb& box, const Eigen::Vector3d& by) {
  box.min += by;
  box.max += by;
}

// 60 calls. Every box drifts by up to 0.1 mm a call on each axis, at most 6 mm in all, which
// stays within the skin of about 1 cm: the drift alone never builds the list again. Every
// tenth call one box jumps into the lattice's second ring of neighbours (new pairs), upwards
// and downwards in turn, so that only its upper or only its lower bounds show it.
void expect_all_pairs_while_boxes_drift_and_jump(int dims) {
  std::vector<Aabb> boxes = lattice(dims);
  OverlappingPairCache cache;  // skin 0.1 of the extent 0.1004 m
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> drift(-1e-4, 1e-4);
  std::uniform_int_distribution<std::size_t> pick(0, boxes.size() - 1);
  const auto drift_by = [&] {
    return Eigen::Vector3d(drift(rng), drift(rng), dims == 2 ? 0.0 : drift(rng));
  };
  const Eigen::Vector3d jump(0.15, 0.12, dims == 2 ? 0.0 : 0.12);
  OverlappingPairs pairs;
  constexpr int kCalls = 60;
  int jumps = 0;
  for (int call = 0; call < kCalls; ++call) {
    for (Aabb& box : boxes) shift(box, drift_by());
    if (call % 10 == 9) shift(boxes[pick(rng)], (jumps++ % 2 == 0 ? 1.0 : -1.0) * jump);
    cache.find(boxes, pairs);
    const OverlappingPairs expected = find_overlapping_pairs_brute_force(boxes);
    ASSERT_GT(expected.size(), 1000u) << call;  // enough pairs for the comparison to mean much
    ASSERT_EQ(pairs, expected) << "call " << call;
  }
  // Built once, then once at each jump, and kept across every other call.
  EXPECT_EQ(cache.builds(), static_cast<std::size_t>(1 + jumps));
}

TEST(OverlappingPairCache, EqualsAllPairsWhileSquaresDriftAndJump) {
  expect_all_pairs_while_boxes_drift_and_jump(2);
}

TEST(OverlappingPairCache, EqualsAllPairsWhileCubesDriftAndJump) {
  expect_all_pairs_while_boxes_drift_and_jump(3);
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
  // A refusal leaves no list behind, not even for no boxes at all.
  std::vector<Aabb> broken = boxes;
  broken[7].min.y() = nan;
  EXPECT_THROW(cache.find(broken, pairs), std::invalid_argument);
  cache.find({}, pairs);
  EXPECT_TRUE(pairs.empty());
}

TEST(OverlappingPairCache, RefusesABadSkinFraction) {
  for (const double bad :
       {-0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(OverlappingPairCache{bad}, std::invalid_argument) << bad;
}

}  // namespace
}  // namespace impactbench::model
