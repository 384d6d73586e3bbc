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

// A box as the grid files it: its bounds, its cell's key and its index in the caller's list.
struct FiledBox {
  double min[3];
  double max[3];
  std::uint64_t key;
  int index;
  bool overlaps(const FiledBox& other) const {
    return min[0] <= other.max[0] && min[1] <= other.max[1] && min[2] <= other.max[2] &&
           other.min[0] <= max[0] && other.min[1] <= max[1] && other.min[2] <= max[2];
  }
};

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
  // Each box's cell in doubles, kept for the integer cells below (floor costs a dozen
  // instructions per axis without SSE4.1).
  thread_local std::vector<Eigen::Vector3d> floored;
  floored.resize(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i)
    floored[i] = cell_floor(boxes[i].min);
  Eigen::Vector3d lowest_cell = floored[0];
  Eigen::Vector3d highest_cell = lowest_cell;
  for (const Eigen::Vector3d& c : floored) {
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
  thread_local std::vector<int> fill;
  cell_of_box.resize(static_cast<std::size_t>(n));
  key_of_box.resize(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    cell_of_box[i] = floored[i].cast<std::int64_t>() - lowest;
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
  // The boxes copied in bucket order (within a bucket, by index): the scans below read their
  // partners' bounds in sequence instead of through an index array.
  thread_local std::vector<FiledBox> filed;
  filed.resize(static_cast<std::size_t>(n));
  fill.assign(bucket_start.begin(), bucket_start.end() - 1);
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Aabb& b = boxes[k];
    filed[static_cast<std::size_t>(fill[bucket_of(key_of_box[k])]++)] = {
        {b.min.x(), b.min.y(), b.min.z()}, {b.max.x(), b.max.y(), b.max.z()}, key_of_box[k], i};
  }

  // Each pair of neighbouring cells is visited once: box a meets the boxes after it in its own
  // cell and every box of the cells after it, (x+1, y, z), the row x−1…x+1 at (y+1, z) and the
  // rows at z+1 (13 of the 26 neighbours in 3-D, 4 of 8 in the plane; with direct buckets a row
  // is one contiguous range of `filed`, and a bucket holds one cell only). Each overlapping pair
  // is found exactly once, and kept as (min, max).
  thread_local std::vector<std::pair<int, int>> found;
  found.clear();
  const auto test_range = [&](const FiledBox& a, int first, int last, bool check_key,
                              std::uint64_t lowest_key, std::uint64_t highest_key)
      __attribute__((always_inline)) {
    for (int p = first; p < last; ++p) {
      const FiledBox& b = filed[static_cast<std::size_t>(p)];
      if (check_key && (b.key < lowest_key || b.key > highest_key)) continue;
      if (a.overlaps(b)) found.emplace_back(std::min(a.index, b.index), std::max(a.index, b.index));
    }
  };
  // The boxes filed in cells x_first…x_last of the row (y, z).
  const auto scan_row = [&](const FiledBox& a, std::int64_t y, std::int64_t z, std::int64_t x_first,
                            std::int64_t x_last) __attribute__((always_inline)) {
    if (y < 0 || y >= extent.y()) return;
    x_first = std::max<std::int64_t>(x_first, 0);
    x_last = std::min<std::int64_t>(x_last, extent.x() - 1);
    if (x_first > x_last) return;
    const std::uint64_t row = key_of(CellIndex(0, y, z));
    if (direct) {
      test_range(a, bucket_start[row + x_first], bucket_start[row + x_last + 1], false, 0, 0);
      return;
    }
    for (std::int64_t x = x_first; x <= x_last; ++x) {
      const std::uint64_t key = row + static_cast<std::uint64_t>(x);
      const std::size_t b = bucket_of(key);
      test_range(a, bucket_start[b], bucket_start[b + 1], true, key, key);
    }
  };
  for (std::size_t b = 0; b < buckets; ++b) {
    const int bucket_end = bucket_start[b + 1];
    for (int p = bucket_start[b]; p < bucket_end; ++p) {
      const FiledBox& a = filed[static_cast<std::size_t>(p)];
      const CellIndex& home = cell_of_box[static_cast<std::size_t>(a.index)];
      const std::int64_t x = home.x(), y = home.y(), z = home.z();
      // Its own cell after it, then (x+1, y, z): one range when buckets are cells.
      if (direct) {
        const std::uint64_t after = a.key + (x + 1 < extent.x() ? 1 : 0);
        test_range(a, p + 1, bucket_start[after + 1], false, 0, 0);
      } else {
        test_range(a, p + 1, bucket_end, true, a.key, a.key);
        scan_row(a, y, z, x + 1, x + 1);
      }
      scan_row(a, y + 1, z, x - 1, x + 1);
      if (z + 1 < extent.z())
        for (std::int64_t dy = -1; dy <= 1; ++dy) scan_row(a, y + dy, z + 1, x - 1, x + 1);
    }
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
  // A first index has a handful of partners: sorted by insertion, without std::sort's set-up
  // (std::sort for many, as a box far larger than the others has).
  constexpr int kInsertionSortLimit = 16;
  for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {
    const int last = first_start[k + 1];
    if (last - first_start[k] > kInsertionSortLimit) {
      std::sort(pairs.begin() + first_start[k], pairs.begin() + last);
      continue;
    }
    for (int p = first_start[k] + 1; p < last; ++p) {
      const auto pair = pairs[static_cast<std::size_t>(p)];
      int q = p;
      for (; q > first_start[k] && pairs[static_cast<std::size_t>(q) - 1].second > pair.second; --q)
        pairs[static_cast<std::size_t>(q)] = pairs[static_cast<std::size_t>(q) - 1];
      pairs[static_cast<std::size_t>(q)] = pair;
    }
  }
}

}  // namespace impactbench::model
