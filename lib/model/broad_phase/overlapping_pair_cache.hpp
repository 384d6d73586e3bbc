#pragma once
// The overlapping pairs of boxes that move little between calls (a time stepper's bodies from
// one step to the next), from a list kept across calls: the pairs of the boxes fattened by a
// skin when the list is built, tested again exactly at each call. While every box lies inside
// its fattened box, two boxes that overlap have fattened boxes that overlap, so the list holds
// every overlapping pair, and the exact test leaves precisely the pairs find_overlapping_pairs
// gives, in its order. A box that leaves its fattened box, or another number of boxes, builds
// the list again. The test reads nothing but the boxes, so one cache may serve any caller (a
// thread's systems share one). Box2D's and Bullet's fat bounding boxes serve the same purpose.
#include <cstddef>
#include <vector>

#include "lib/model/broad_phase/uniform_grid.hpp"

namespace impactbench::model {

class OverlappingPairCache {
 public:
  /// The skin as a fraction of the largest box's extent: large enough that a settled or slowly
  /// moving pile keeps its list for many steps, small enough that the list holds few pairs
  /// beyond the overlapping ones.
  static constexpr double kDefaultSkinFraction = 0.1;

  explicit OverlappingPairCache(double skin_fraction = kDefaultSkinFraction);

  /// What find_overlapping_pairs(boxes, pairs) gives (boxes must be finite), from the kept list
  /// when every box still lies inside its fattened box.
  void find(const std::vector<Aabb>& boxes, OverlappingPairs& pairs);

  /// How many times the list has been built.
  std::size_t builds() const { return builds_; }

 private:
  bool holds(const std::vector<Aabb>& boxes) const;
  void build(const std::vector<Aabb>& boxes);

  double skin_fraction_;
  std::vector<Aabb> fattened_;
  OverlappingPairs fattened_pairs_;
  std::size_t builds_ = 0;
};

}  // namespace impactbench::model
