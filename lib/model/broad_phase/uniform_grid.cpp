#include "lib/model/broad_phase/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace impactbench::model {
namespace {

using CellIndex = Eigen::Matrix<std::int64_t, 3, 1>;

// MurmurHash3's 64-bit finalizer: spreads cell keys over the low bits that pick a bucket.
std::uint64_t mix(std::uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33;
  return h;
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

  // Cells are numbered x + nx (y + ny z) from the lowest cell of all boxes: one integer per
  // cell, so equal cells compare as integers. A scene spanning more cells than 64 bits count
  // (boxes spread over astronomically more than their size) falls back to testing all pairs.
  // The bounds are taken in doubles first: a cell index beyond 64 bits must not be cast.
  auto cell_floor = [inv_cell](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return (p * inv_cell).array().floor().matrix();
  };
  Eigen::Vector3d lowest_cell = cell_floor(boxes[0].min);
  Eigen::Vector3d highest_cell = cell_floor(boxes[0].max);
  for (const Aabb& b : boxes) {
    lowest_cell = lowest_cell.cwiseMin(cell_floor(b.min));
    highest_cell = highest_cell.cwiseMax(cell_floor(b.max));
  }
  const Eigen::Vector3d cell_extent = highest_cell - lowest_cell + Eigen::Vector3d::Ones();
  constexpr double kMaxCells = 4.0e18;  // below 2^63
  if (!(cell_extent.prod() <= kMaxCells) || !(lowest_cell.cwiseAbs().maxCoeff() <= kMaxCells) ||
      !(highest_cell.cwiseAbs().maxCoeff() <= kMaxCells))
    return find_overlapping_pairs_brute_force(boxes);
  const CellIndex lowest = lowest_cell.cast<std::int64_t>();
  const CellIndex extent = cell_extent.cast<std::int64_t>();
  const auto key_of = [&](const CellIndex& c) -> std::uint64_t {
    const CellIndex r = c - lowest;
    return static_cast<std::uint64_t>(r.x() + extent.x() * (r.y() + extent.y() * r.z()));
  };

  // Every (cell, box) incidence, bucketed by cell with a counting sort (two passes, no per-cell
  // containers; the scratch arrays are kept between calls). The buckets are the cells
  // themselves when they are few, else the cells' keys hashed (then distinct cells may share a
  // bucket: boxes are compared only when their cells are equal).
  struct Entry {
    std::uint64_t cell;
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
        for (std::int64_t z = lo.z(); z <= hi.z(); ++z)
          entries.push_back({key_of(CellIndex(x, y, z)), i});
  }
  const std::uint64_t cells = static_cast<std::uint64_t>(extent.prod());
  const bool direct = cells <= 4 * entries.size();
  std::size_t buckets = 1;
  if (direct) {
    buckets = cells;
  } else {
    while (buckets < 2 * entries.size()) buckets *= 2;
  }
  const std::uint64_t mask = buckets - 1;
  const auto bucket_of = [&](std::uint64_t cell) -> std::size_t {
    return direct ? cell : mix(cell) & mask;
  };
  bucket_start.assign(buckets + 1, 0);
  for (const Entry& e : entries) ++bucket_start[bucket_of(e.cell) + 1];
  for (std::size_t b = 0; b < buckets; ++b) bucket_start[b + 1] += bucket_start[b];
  bucketed.resize(entries.size());
  {
    thread_local std::vector<int> fill;
    fill.assign(bucket_start.begin(), bucket_start.end() - 1);
    for (const Entry& e : entries)  // in box order: each bucket lists its boxes ascending
      bucketed[static_cast<std::size_t>(fill[bucket_of(e.cell)]++)] = e;
  }

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
        if (key_of(cell_of(box_a.min.cwiseMax(box_c.min))) != a.cell) continue;
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
