#include "lib/model/broad_phase/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

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
  auto cell_of = [inv_cell](const Eigen::Vector3d& p) -> CellIndex {
    return (p * inv_cell).array().floor().cast<std::int64_t>();
  };

  // Every (cell, box) incidence, bucketed by the cell's hash with a counting sort (two passes,
  // no per-cell containers; the scratch arrays are kept between calls). Distinct cells may share
  // a bucket: boxes are compared only when their cells are equal.
  struct Entry {
    CellIndex cell;
    int box;
  };
  thread_local std::vector<Entry> entries;
  thread_local std::vector<Entry> bucketed;
  thread_local std::vector<int> bucket_start;
  entries.clear();
  for (int i = 0; i < n; ++i) {
    const CellIndex lo = cell_of(boxes[i].min);
    const CellIndex hi = cell_of(boxes[i].max);
    for (std::int64_t x = lo.x(); x <= hi.x(); ++x)
      for (std::int64_t y = lo.y(); y <= hi.y(); ++y)
        for (std::int64_t z = lo.z(); z <= hi.z(); ++z) entries.push_back({CellIndex(x, y, z), i});
  }
  std::size_t buckets = 1;
  while (buckets < 2 * entries.size()) buckets *= 2;
  const std::uint64_t mask = buckets - 1;
  bucket_start.assign(buckets + 1, 0);
  for (const Entry& e : entries) ++bucket_start[(hash_cell(e.cell) & mask) + 1];
  for (std::size_t b = 0; b < buckets; ++b) bucket_start[b + 1] += bucket_start[b];
  bucketed.resize(entries.size());
  {
    thread_local std::vector<int> fill;
    fill.assign(bucket_start.begin(), bucket_start.end() - 1);
    for (const Entry& e : entries)  // in box order: each bucket lists its boxes ascending
      bucketed[static_cast<std::size_t>(fill[hash_cell(e.cell) & mask]++)] = e;
  }

  // Pairs grouped by their smaller index, so the sorted output needs no global sort.
  thread_local std::vector<std::pair<int, int>> found;
  found.clear();
  for (std::size_t b = 0; b < buckets; ++b) {
    const int first = bucket_start[b];
    const int last = bucket_start[b + 1];
    for (int p = first; p < last; ++p) {
      const Entry& a = bucketed[static_cast<std::size_t>(p)];
      for (int q = p + 1; q < last; ++q) {
        const Entry& c = bucketed[static_cast<std::size_t>(q)];
        if (c.box == a.box || c.cell != a.cell) continue;
        const Aabb& box_a = boxes[static_cast<std::size_t>(a.box)];
        const Aabb& box_c = boxes[static_cast<std::size_t>(c.box)];
        if (!box_a.overlaps(box_c)) continue;
        // Two boxes may share several cells: report the pair only from the cell holding the
        // lowest corner of their overlap, so it is found exactly once.
        if (cell_of(box_a.min.cwiseMax(box_c.min)) != a.cell) continue;
        found.emplace_back(std::min(a.box, c.box), std::max(a.box, c.box));
      }
    }
  }
  // Sorted by a counting sort on the first index, then each body's few partners in place.
  thread_local std::vector<int> group_start;
  group_start.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const auto& pair : found) ++group_start[static_cast<std::size_t>(pair.first) + 1];
  for (int i = 0; i < n; ++i) group_start[i + 1] += group_start[i];
  std::vector<std::pair<int, int>> pairs(found.size());
  {
    thread_local std::vector<int> fill;
    fill.assign(group_start.begin(), group_start.end() - 1);
    for (const auto& pair : found) pairs[static_cast<std::size_t>(fill[pair.first]++)] = pair;
  }
  for (int i = 0; i < n; ++i)
    std::sort(pairs.begin() + group_start[i], pairs.begin() + group_start[i + 1]);
  return pairs;
}

}  // namespace impactbench::model
