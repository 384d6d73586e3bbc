#include "lib/engines/moreau_jean/block_diagonal_inverse.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>

#include "lib/model/growing_capacity.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

// "[first, last]" (built by appends: GCC 12 warns falsely on "[" + std::string).
std::string block_range(int first, int last) {
  std::string s = "[";
  s += std::to_string(first);
  s += ", ";
  s += std::to_string(last);
  s += "]";
  return s;
}

// Appends the columns of one block's inverse to `result`, the nonzeros of each in ascending rows,
// after its first `count` entries: the blocks are disjoint and inverted in order, so M⁻¹ is
// written straight into compressed storage (the entries setFromTriplets would put there, and
// those of startVec and insertBack, without their bookkeeping per entry). The storage's size is
// its room (invert_block_diagonal cuts it to `count` at the end), grown when the block may not
// fit.
template <typename Inverse>
void append_block(const Inverse& inverse, int start, int size, Eigen::SparseMatrix<double>& result,
                  Eigen::Index& count) {
  auto& storage = result.data();
  const Eigen::Index needed = count + static_cast<Eigen::Index>(size) * size;
  if (needed > storage.size()) storage.resize(std::max(needed, 2 * storage.size()));
  int* outer = result.outerIndexPtr();
  int* inner = result.innerIndexPtr();
  double* values = result.valuePtr();
  for (int c = 0; c < size; ++c) {
    outer[start + c] = static_cast<int>(count);
    for (int r = 0; r < size; ++r) {
      if (inverse(r, c) == 0.0) continue;
      inner[count] = start + r;
      values[count] = inverse(r, c);
      ++count;
    }
  }
}

// B⁻¹ from B's Cholesky factor L (B = L Lᵀ; only the lower triangle of `L` is read): L Y = I, then
// Lᵀ X = Y, column by column. These are the operations, in their order, of Eigen 3.4's triangular
// solve with several right-hand sides when the whole triangle fits in one of its panels (at least 4
// rows wide: 3 × 3 always does), so X has the bits of llt.solve(Identity) without that solve's
// blocking and packing (which took about half of a sphere pile's inversion). The tests compare the
// two.
template <int N>
Eigen::Matrix<double, N, N> inverse_from_cholesky_factor(const Eigen::Matrix<double, N, N>& L) {
  Eigen::Matrix<double, N, N> x = Eigen::Matrix<double, N, N>::Identity();
  for (int i = 0; i < N; ++i) {  // forward: each row scaled by 1/L_ii, then eliminated below
    const double a = 1.0 / L(i, i);
    for (int j = 0; j < N; ++j) {
      x(i, j) *= a;
      for (int t = i + 1; t < N; ++t) x(t, j) -= x(i, j) * L(t, i);
    }
  }
  for (int i = N - 1; i >= 0; --i) {  // backward: the solved rows summed from zero, then scaled
    const double a = 1.0 / L(i, i);
    for (int j = 0; j < N; ++j) {
      double b = 0.0;
      for (int t = i + 1; t < N; ++t) b += L(t, i) * x(t, j);
      x(i, j) = (x(i, j) - b) * a;
    }
  }
  return x;
}

// Blocks of up to 3 × 3 (a planar body's, diagonal; a spatial body's world inertia; the translation
// of either is three 1 × 1 blocks): a fixed-size factorisation, no heap and no general-size
// kernels. Returns false when the block fails the factorisation's test
// (the general path then reports it).
template <int N>
bool invert_fixed_block(const Eigen::SparseMatrix<double>& matrix, int start,
                        BlockFactorization factorization, Eigen::SparseMatrix<double>& result,
                        Eigen::Index& count) {
  using Block = Eigen::Matrix<double, N, N>;
  Block block = Block::Zero();
  for (int c = start; c < start + N; ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, c); it; ++it)
      block(static_cast<int>(it.row()) - start, c - start) = it.value();
  Block inverse;
  if (block.isDiagonal(0.0)) {  // the common case: a reciprocal per entry
    const auto diagonal = block.diagonal();
    const bool valid = factorization == BlockFactorization::kCholesky
                           ? (diagonal.array() > 0.0).all()
                           : (diagonal.array() != 0.0).all();
    if (!valid) return false;
    inverse = diagonal.cwiseInverse().asDiagonal();
  } else if (factorization == BlockFactorization::kCholesky) {
    const Eigen::LLT<Block> llt(block);
    if (llt.info() != Eigen::Success) return false;
    inverse = inverse_from_cholesky_factor<N>(llt.matrixLLT());  // L in its lower triangle
  } else {
    const Eigen::FullPivLU<Block> lu(block);
    if (!lu.isInvertible()) return false;
    inverse = lu.solve(Block::Identity());  // what inverse() does, without copying lu
  }
  append_block(inverse, start, N, result, count);
  return true;
}

bool invert_small_block(const Eigen::SparseMatrix<double>& matrix, int start, int size,
                        BlockFactorization factorization, Eigen::SparseMatrix<double>& result,
                        Eigen::Index& count) {
  switch (size) {
    case 1:
      return invert_fixed_block<1>(matrix, start, factorization, result, count);
    case 2:
      return invert_fixed_block<2>(matrix, start, factorization, result, count);
    case 3:
      return invert_fixed_block<3>(matrix, start, factorization, result, count);
    default:
      return false;
  }
}

}  // namespace

Eigen::SparseMatrix<double> invert_block_diagonal(const Eigen::SparseMatrix<double>& matrix,
                                                  BlockFactorization factorization) {
  Eigen::SparseMatrix<double> result;
  invert_block_diagonal(matrix, factorization, result);
  return result;
}

void invert_block_diagonal(const Eigen::SparseMatrix<double>& matrix,
                           BlockFactorization factorization, Eigen::SparseMatrix<double>& result) {
  const int n = static_cast<int>(matrix.rows());
  if (matrix.cols() != n) throw std::invalid_argument("matrix to invert is not square");

  // reach[i]: the largest index coupled to i by a nonzero; a block ends where no earlier
  // index reaches past it (scratch kept per thread: a time stepper inverts every step).
  thread_local std::vector<int> reach;
  reach.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) reach[i] = i;
  for (int j = 0; j < matrix.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, j); it; ++it) {
      if (!std::isfinite(it.value()))
        throw std::invalid_argument("matrix to invert has a non-finite entry at (" +
                                    std::to_string(it.row()) + ", " + std::to_string(it.col()) +
                                    ")");
      const int lo = static_cast<int>(std::min(it.row(), it.col()));
      const int hi = static_cast<int>(std::max(it.row(), it.col()));
      reach[lo] = std::max(reach[lo], hi);
    }
  }

  result.resize(n, n);
  model::reserve_growing(result, matrix.nonZeros() + n);
  result.data().resize(result.data().allocatedSize());  // all the room, written in place
  Eigen::Index count = 0;
  int start = 0;
  while (start < n) {
    int end = reach[start];
    for (int i = start; i <= end; ++i) end = std::max(end, reach[i]);
    const int size = end - start + 1;
    if (size <= 3 && invert_small_block(matrix, start, size, factorization, result, count)) {
      start = end + 1;
      continue;
    }
    const Eigen::MatrixXd block = Eigen::MatrixXd(matrix.block(start, start, size, size));
    Eigen::MatrixXd inverse;
    if (factorization == BlockFactorization::kCholesky) {
      const Eigen::LLT<Eigen::MatrixXd> llt(block);
      if (llt.info() != Eigen::Success)
        throw std::invalid_argument("mass matrix block " + block_range(start, end) +
                                    " is not positive definite");
      inverse = llt.solve(Eigen::MatrixXd::Identity(size, size));
    } else {
      const Eigen::FullPivLU<Eigen::MatrixXd> lu(block);
      if (!lu.isInvertible())
        throw std::invalid_argument("iteration matrix block " + block_range(start, end) +
                                    " is singular");
      inverse = lu.inverse();
    }
    append_block(inverse, start, size, result, count);
    start = end + 1;
  }
  result.outerIndexPtr()[n] = static_cast<int>(count);
  result.data().resize(count);
}

}  // namespace impactbench::engines::moreau_jean
