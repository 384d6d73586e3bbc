#pragma once
// Broad phase by a uniform grid (cells numbered by integers, bucketed by a counting sort; hashed
// when the scene spans many more cells than boxes): cell edge = the largest box extent, each
// axis-aligned box is filed under the cell of its lowest corner, and a box is tested only
// against the boxes of its own and the adjacent cells. For piles of similar-sized bodies this
// costs O(N).
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace impactbench::model {

struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
  bool overlaps(const Aabb& other) const {
    return (min.array() <= other.max.array()).all() && (other.min.array() <= max.array()).all();
  }
};

using OverlappingPairs = std::vector<std::pair<int, int>>;

/// Every pair (i, j), i < j, whose boxes overlap, sorted lexicographically, into `pairs` (its
/// contents replaced, its storage kept: a stepper that keeps it allocates nothing once it is
/// large enough). Boxes must be finite.
void find_overlapping_pairs(const std::vector<Aabb>& boxes, OverlappingPairs& pairs);
OverlappingPairs find_overlapping_pairs(const std::vector<Aabb>& boxes);

/// The same by testing all N²/2 pairs: the oracle for tests, and the choice for tiny systems.
void find_overlapping_pairs_brute_force(const std::vector<Aabb>& boxes, OverlappingPairs& pairs);
OverlappingPairs find_overlapping_pairs_brute_force(const std::vector<Aabb>& boxes);

}  // namespace impactbench::model
