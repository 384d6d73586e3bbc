#pragma once
// Buffers refilled every step to a count that rises slowly (a pile's contacts while it forms)
// would be reallocated at every rise if sized exactly (std::vector::assign and Eigen's sparse
// reserve do): these at least double the capacity when it must grow, so such a buffer is
// reallocated O(log count) times.
#include <algorithm>
#include <cstddef>
#include <vector>

#include <Eigen/SparseCore>

namespace impactbench::model {

/// Room for `count` elements in `buffer`.
template <typename T>
void reserve_growing(std::vector<T>& buffer, std::size_t count) {
  if (count > buffer.capacity()) buffer.reserve(std::max(count, 2 * buffer.capacity()));
}

/// Room for `entries` nonzeros in `matrix`, which must be empty (just resized) and compressed.
template <typename Scalar, int Options, typename StorageIndex>
void reserve_growing(Eigen::SparseMatrix<Scalar, Options, StorageIndex>& matrix,
                     Eigen::Index entries) {
  const Eigen::Index capacity = matrix.data().allocatedSize();
  matrix.reserve(entries > capacity ? std::max(entries, 2 * capacity) : entries);
}

}  // namespace impactbench::model
