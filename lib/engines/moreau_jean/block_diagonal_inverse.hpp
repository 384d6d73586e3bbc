#pragma once
// M⁻¹ of a symmetric positive definite mass matrix that is block diagonal (free rigid bodies:
// 3×3 planar, 6×6 spatial; an articulated system: one dense block). The blocks are found from
// the sparsity pattern, so M⁻¹ keeps M's structure and W = J M⁻¹ Jᵀ stays sparse for piles.
#include <Eigen/SparseCore>

namespace impactbench::engines::moreau_jean {

/// How each diagonal block is factorised.
enum class BlockFactorization {
  kCholesky,  ///< symmetric positive definite blocks (a mass matrix); others are an error
  kLu,        ///< any invertible blocks (an iteration matrix M + hθC + h²θ²K)
};

/// Inverts each diagonal block of `matrix`. Throws std::invalid_argument if `matrix` is not
/// square, not finite, or a block is not positive definite (kCholesky) or singular (kLu); the
/// message names the block's first and last velocity index.
Eigen::SparseMatrix<double> invert_block_diagonal(
    const Eigen::SparseMatrix<double>& matrix,
    BlockFactorization factorization = BlockFactorization::kCholesky);
/// The same into `result`, reusing its storage (its contents are unspecified after a throw).
void invert_block_diagonal(const Eigen::SparseMatrix<double>& matrix,
                           BlockFactorization factorization, Eigen::SparseMatrix<double>& result);

}  // namespace impactbench::engines::moreau_jean
