#include "lib/model/broad_phase/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace impactbench::model {
namespace {

using CellIndex = Eigen::Matrix<std::int64_t, 3, 1>;

std::uint64_t hash_cell(const CellIndex& c) {
  // Large odd multipliers spread neighbouring cells over the table (Teschner et al. 2003).
  return static_cast<std::uint64_t>(c.x()) * 73856093ULL ^
         static_cast<std::uint64_t>(c.y()) * 19349663ULL ^
         static_cast<std::uint64_t>(c.z()) * 83492791ULL;
}

}  // namespace

std::vector<std::pair<int, int>> find_overlapping_pairs_brute_force(const std::vector<Aabb>& boxes) {
  std::vector<std::pair<int, int>> pairs;
  const int n = static_cast<int>(boxes.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
  return pairs;
}

std::vector<std::pair<int, int>> find_overlapping_pairs(const std::vector<Aabb>& boxes) {
  const int n = static_cast<int>(boxes.size());
  if (n < 32) return find_overlapping_pairs_brute_force(boxes);

  double cell = 0.0;
  for (const Aabb& b : boxes) {
    if (!b.min.allFinite() || !b.max.allFinite())
      throw std::invalid_argument("broad phase: non-finite bounding box");
    cell = std::max(cell, (b.max - b.min).maxCoeff());
  }
  if (cell <= 0.0) cell = 1.0;
  const double inv_cell = 1.0 / cell;

  // Cell hash -> indices of boxes overlapping that cell. Distinct cells may share a hash; the
  // exact overlap test below makes collisions harmless.
  std::unordered_map<std::uint64_t, std::vector<int>> buckets;
  buckets.reserve(static_cast<std::size_t>(n) * 2);
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < n; ++i) {
    const CellIndex lo = (boxes[i].min * inv_cell).array().floor().cast<std::int64_t>();
    const CellIndex hi = (boxes[i].max * inv_cell).array().floor().cast<std::int64_t>();
    for (std::int64_t x = lo.x(); x <= hi.x(); ++x)
      for (std::int64_t y = lo.y(); y <= hi.y(); ++y)
        for (std::int64_t z = lo.z(); z <= hi.z(); ++z) {
          std::vector<int>& bucket = buckets[hash_cell(CellIndex(x, y, z))];
          for (int j : bucket)
            if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(j, i);
          bucket.push_back(i);
        }
  }
  // A pair sharing several cells was found once per shared cell.
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace impactbench::model
