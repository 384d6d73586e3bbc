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

std::vector<std::pair<int, int>> find_overlapping_pairs_brute_force(
    const std::vector<Aabb>& boxes) {
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

  double cell_size = 0.0;
  for (const Aabb& b : boxes) {
    if (!b.min.allFinite() || !b.max.allFinite())
      throw std::invalid_argument("broad phase: non-finite bounding box");
    cell_size = std::max(cell_size, (b.max - b.min).maxCoeff());
  }
  if (cell_size <= 0.0) cell_size = 1.0;
  const double inv_cell = 1.0 / cell_size;

  // Cell hash -> indices of boxes overlapping that cell. Distinct cells may share a hash; the
  // exact overlap test below makes collisions harmless.
  std::unordered_map<std::uint64_t, std::vector<int>> buckets;
  buckets.reserve(static_cast<std::size_t>(n) * 2);
  auto cell_of = [inv_cell](const Eigen::Vector3d& p) -> CellIndex {
    return (p * inv_cell).array().floor().cast<std::int64_t>();
  };
  // Pairs grouped by their smaller index, so the sorted output needs no global sort.
  std::vector<std::vector<int>> partners(n);
  for (int i = 0; i < n; ++i) {
    const CellIndex lo = cell_of(boxes[i].min);
    const CellIndex hi = cell_of(boxes[i].max);
    for (std::int64_t x = lo.x(); x <= hi.x(); ++x)
      for (std::int64_t y = lo.y(); y <= hi.y(); ++y)
        for (std::int64_t z = lo.z(); z <= hi.z(); ++z) {
          const CellIndex cell(x, y, z);
          std::vector<int>& bucket = buckets[hash_cell(cell)];
          for (int j : bucket) {
            if (!boxes[i].overlaps(boxes[j])) continue;
            // Two boxes may share several cells: report the pair only from the cell holding
            // the lowest corner of their overlap, so it is found exactly once.
            if (cell_of(boxes[i].min.cwiseMax(boxes[j].min)) != cell) continue;
            partners[j].push_back(i);
          }
          bucket.push_back(i);
        }
  }
  std::vector<std::pair<int, int>> pairs;
  for (int j = 0; j < n; ++j) {
    std::sort(partners[j].begin(), partners[j].end());  // a handful per body
    for (int i : partners[j]) pairs.emplace_back(j, i);
  }
  return pairs;
}

}  // namespace impactbench::model
