#include "lib/model/broad_phase/overlapping_pair_cache.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lib/output/number_text.hpp"

namespace impactbench::model {

OverlappingPairCache::OverlappingPairCache(double skin_fraction) : skin_fraction_(skin_fraction) {
  if (!(std::isfinite(skin_fraction) && skin_fraction >= 0.0))
    throw std::invalid_argument("broad phase: skin fraction must be finite and >= 0, got " +
                                output::number_text(skin_fraction));
}

void OverlappingPairCache::find(const std::vector<Aabb>& boxes, OverlappingPairs& pairs) {
  if (!holds(boxes)) build(boxes);
  pairs.clear();
  for (const auto& pair : fattened_pairs_)
    if (boxes[static_cast<std::size_t>(pair.first)].overlaps(
            boxes[static_cast<std::size_t>(pair.second)]))
      pairs.push_back(pair);
}

// A non-finite box fails these tests (NaN compares false) and goes to build, which refuses it.
bool OverlappingPairCache::holds(const std::vector<Aabb>& boxes) const {
  if (boxes.size() != fattened_.size()) return false;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Aabb& box = boxes[i];
    const Aabb& fat = fattened_[i];
    if (!((box.min.array() >= fat.min.array()).all() && (box.max.array() <= fat.max.array()).all()))
      return false;
  }
  return true;
}

void OverlappingPairCache::build(const std::vector<Aabb>& boxes) {
  // A refused box leaves no list behind: neither fattened boxes nor their pairs, which a later
  // call with as many boxes (none, say) would otherwise take for its own.
  fattened_.clear();
  fattened_pairs_.clear();
  ++builds_;
  double extent_max = 0.0;
  for (const Aabb& b : boxes) extent_max = std::max(extent_max, (b.max - b.min).maxCoeff());
  const Eigen::Vector3d skin = Eigen::Vector3d::Constant(skin_fraction_ * extent_max);
  thread_local std::vector<Aabb> fattened;  // kept per thread, as the grid's scratch
  fattened.resize(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i)
    fattened[i] = {boxes[i].min - skin, boxes[i].max + skin};
  find_overlapping_pairs(fattened, fattened_pairs_);
  fattened_.swap(fattened);
}

}  // namespace impactbench::model
