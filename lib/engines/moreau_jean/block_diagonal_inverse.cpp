#include "lib/engines/moreau_jean/block_diagonal_inverse.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace impactbench::engines::moreau_jean {

Eigen::SparseMatrix<double> invert_block_diagonal(const Eigen::SparseMatrix<double>& mass) {
  const int n = static_cast<int>(mass.rows());
  if (mass.cols() != n) throw std::invalid_argument("mass matrix is not square");

  // reach[i]: the largest index coupled to i by a nonzero; a block ends where no earlier
  // index reaches past it.
  std::vector<int> reach(n);
  for (int i = 0; i < n; ++i) reach[i] = i;
  for (int j = 0; j < mass.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(mass, j); it; ++it) {
      if (!std::isfinite(it.value()))
        throw std::invalid_argument("mass matrix has a non-finite entry at (" +
                                    std::to_string(it.row()) + ", " + std::to_string(it.col()) +
                                    ")");
      const int lo = static_cast<int>(std::min(it.row(), it.col()));
      const int hi = static_cast<int>(std::max(it.row(), it.col()));
      reach[lo] = std::max(reach[lo], hi);
    }
  }

  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(mass.nonZeros()) + n);
  int start = 0;
  while (start < n) {
    int end = reach[start];
    for (int i = start; i <= end; ++i) end = std::max(end, reach[i]);
    const int size = end - start + 1;
    const Eigen::MatrixXd block = Eigen::MatrixXd(mass.block(start, start, size, size));
    const Eigen::LLT<Eigen::MatrixXd> llt(block);
    if (llt.info() != Eigen::Success)
      throw std::invalid_argument("mass matrix block [" + std::to_string(start) + ", " +
                                  std::to_string(end) + "] is not positive definite");
    const Eigen::MatrixXd inverse = llt.solve(Eigen::MatrixXd::Identity(size, size));
    for (int c = 0; c < size; ++c)
      for (int r = 0; r < size; ++r)
        if (inverse(r, c) != 0.0) triplets.emplace_back(start + r, start + c, inverse(r, c));
    start = end + 1;
  }
  Eigen::SparseMatrix<double> result(n, n);
  result.setFromTriplets(triplets.begin(), triplets.end());
  return result;
}

}  // namespace impactbench::engines::moreau_jean
