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

void find_overlapping_pairs_brute_force(const std::vector<Aabb>& boxes, OverlappingPairs& pairs) {
  pairs.clear();
  const int n = static_cast<int>(boxes.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
}

OverlappingPairs find_overlapping_pairs_brute_force(const std::vector<Aabb>& boxes) {
  OverlappingPairs pairs;
  find_overlapping_pairs_brute_force(boxes, pairs);
  return pairs;
}

OverlappingPairs find_overlapping_pairs(const std::vector<Aabb>& boxes) {
  OverlappingPairs pairs;
  find_overlapping_pairs(boxes, pairs);
  return pairs;
}

void find_overlapping_pairs(const std::vector<Aabb>& boxes, OverlappingPairs& pairs) {
  const int n = static_cast<int>(boxes.size());
  if (n < 32) return find_overlapping_pairs_brute_force(boxes, pairs);

  double extent_max = 0.0;
  for (const Aabb& b : boxes) {
    if (!b.min.allFinite() || !b.max.allFinite())
      throw std::invalid_argument("broad phase: non-finite bounding box");
    extent_max = std::max(extent_max, (b.max - b.min).maxCoeff());
  }
  // Each box lives in the one cell holding its lowest corner. With cells at least as wide as
  // every box, the lowest corners of two overlapping boxes are less than one cell apart on each
  // axis, so a box's partners lie in its own cell or the adjacent ones. The cell is widened by
  // a millionth so that rounding in p / cell cannot push a partner two cells away.
  const double cell_size = extent_max > 0.0 ? extent_max * (1.0 + 1e-6) : 1.0;
  const double inv_cell = 1.0 / cell_size;
  auto cell_floor = [inv_cell](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return (p * inv_cell).array().floor().matrix();
  };

  // Cells are numbered x + nx (y + ny z) from the lowest occupied cell: one integer per cell.
  // Beyond a billion cells from the origin the millionth of slack no longer covers rounding,
  // and beyond 64 bits cells cannot be counted: such scenes (boxes spread over astronomically
  // more than their size) are tested pair by pair. The bounds are taken in doubles first: a
  // cell index beyond 64 bits must not be cast.
  Eigen::Vector3d lowest_cell = cell_floor(boxes[0].min);
  Eigen::Vector3d highest_cell = lowest_cell;
  for (const Aabb& b : boxes) {
    const Eigen::Vector3d c = cell_floor(b.min);
    lowest_cell = lowest_cell.cwiseMin(c);
    highest_cell = highest_cell.cwiseMax(c);
  }
  const Eigen::Vector3d cell_extent = highest_cell - lowest_cell + Eigen::Vector3d::Ones();
  constexpr double kMaxCellCoordinate = 1e9;
  constexpr double kMaxCells = 4.0e18;  // below 2^63
  if (!(cell_extent.prod() <= kMaxCells) ||
      !(lowest_cell.cwiseAbs().maxCoeff() <= kMaxCellCoordinate) ||
      !(highest_cell.cwiseAbs().maxCoeff() <= kMaxCellCoordinate))
    return find_overlapping_pairs_brute_force(boxes, pairs);
  const CellIndex lowest = lowest_cell.cast<std::int64_t>();
  const CellIndex extent = cell_extent.cast<std::int64_t>();
  const auto key_of = [&](const CellIndex& relative) -> std::uint64_t {
    return static_cast<std::uint64_t>(relative.x() +
                                      extent.x() * (relative.y() + extent.y() * relative.z()));
  };

  // Boxes bucketed by cell with a counting sort (no per-cell containers; the scratch arrays are
  // kept between calls). The buckets are the cells themselves when they are few, else the
  // cells' keys hashed (then distinct cells may share a bucket: keys are compared exactly).
  thread_local std::vector<CellIndex> cell_of_box;
  thread_local std::vector<std::uint64_t> key_of_box;
  thread_local std::vector<int> bucket_start;
  thread_local std::vector<int> box_in_bucket;
  thread_local std::vector<int> fill;
  cell_of_box.resize(static_cast<std::size_t>(n));
  key_of_box.resize(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    cell_of_box[i] = cell_floor(boxes[i].min).cast<std::int64_t>() - lowest;
    key_of_box[i] = key_of(cell_of_box[i]);
  }
  const std::uint64_t cells = static_cast<std::uint64_t>(extent.prod());
  const bool direct = cells <= 4 * static_cast<std::uint64_t>(n);
  std::size_t buckets = 1;
  if (direct) {
    buckets = cells;
  } else {
    while (buckets < 2 * static_cast<std::size_t>(n)) buckets *= 2;
  }
  const std::uint64_t mask = buckets - 1;
  const auto bucket_of = [&](std::uint64_t key) -> std::size_t {
    return direct ? key : mix(key) & mask;
  };
  bucket_start.assign(buckets + 1, 0);
  for (const std::uint64_t key : key_of_box) ++bucket_start[bucket_of(key) + 1];
  for (std::size_t b = 0; b < buckets; ++b) bucket_start[b + 1] += bucket_start[b];
  box_in_bucket.resize(static_cast<std::size_t>(n));
  fill.assign(bucket_start.begin(), bucket_start.end() - 1);
  for (int i = 0; i < n; ++i)
    box_in_bucket[static_cast<std::size_t>(fill[bucket_of(key_of_box[i])]++)] = i;

  // Each pair of neighbouring cells is visited once: box i meets the boxes j > i of its own cell
  // and every box of the cells after it, (x+1, y, z), the row x−1…x+1 at (y+1, z) and the rows
  // at z+1 (13 of the 26 neighbours in 3-D, 4 of 8 in the plane; with direct buckets a row is
  // one contiguous range). Each overlapping pair is found exactly once, as (min, max).
  thread_local std::vector<std::pair<int, int>> found;
  found.clear();
  // The boxes filed in cells x_first…x_last of the row (y, z), those of i's own cell only when
  // j > i.
  const auto scan_row = [&](int i, std::uint64_t home_key, std::int64_t y, std::int64_t z,
                            std::int64_t x_first, std::int64_t x_last)
      __attribute__((always_inline)) {
    if (y < 0 || y >= extent.y()) return;
    x_first = std::max<std::int64_t>(x_first, 0);
    x_last = std::min<std::int64_t>(x_last, extent.x() - 1);
    const std::uint64_t row = key_of(CellIndex(0, y, z));
    const Aabb& box_i = boxes[static_cast<std::size_t>(i)];
    const auto scan = [&](int first, int last, std::uint64_t lowest_key, std::uint64_t highest_key)
        __attribute__((always_inline)) {
      for (int p = first; p < last; ++p) {
        const int j = box_in_bucket[static_cast<std::size_t>(p)];
        const std::uint64_t key = key_of_box[static_cast<std::size_t>(j)];
        if ((key == home_key && j <= i) || key < lowest_key || key > highest_key) continue;
        if (box_i.overlaps(boxes[static_cast<std::size_t>(j)]))
          found.emplace_back(std::min(i, j), std::max(i, j));
      }
    };
    if (direct) {
      scan(bucket_start[row + x_first], bucket_start[row + x_last + 1], row + x_first,
           row + x_last);
      return;
    }
    for (std::int64_t x = x_first; x <= x_last; ++x) {
      const std::uint64_t key = row + static_cast<std::uint64_t>(x);
      const std::size_t b = bucket_of(key);
      scan(bucket_start[b], bucket_start[b + 1], key, key);
    }
  };
  for (int i = 0; i < n; ++i) {
    const CellIndex& home = cell_of_box[static_cast<std::size_t>(i)];
    const std::uint64_t home_key = key_of_box[static_cast<std::size_t>(i)];
    const std::int64_t x = home.x(), y = home.y(), z = home.z();
    scan_row(i, home_key, y, z, x, x + 1);
    scan_row(i, home_key, y + 1, z, x - 1, x + 1);
    if (z + 1 < extent.z())
      for (std::int64_t dy = -1; dy <= 1; ++dy) scan_row(i, home_key, y + dy, z + 1, x - 1, x + 1);
  }

  // Sorted lexicographically: by the first index with a counting sort, then each first index's
  // few partners in place.
  thread_local std::vector<int> first_start;
  first_start.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const auto& pair : found) ++first_start[static_cast<std::size_t>(pair.first) + 1];
  for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k)
    first_start[k + 1] += first_start[k];
  pairs.resize(found.size());
  fill.assign(first_start.begin(), first_start.end() - 1);
  for (const auto& pair : found)
    pairs[static_cast<std::size_t>(fill[static_cast<std::size_t>(pair.first)]++)] = pair;
  for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k)
    std::sort(pairs.begin() + first_start[k], pairs.begin() + first_start[k + 1]);
}

}  // namespace impactbench::model
