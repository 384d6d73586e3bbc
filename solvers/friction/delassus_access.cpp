#include "solvers/friction/delassus_access.hpp"

namespace impactbench::solvers {

Eigen::VectorXd contact_velocity(const FrictionProblem& problem, const Eigen::VectorXd& r) {
  if (problem.is_factored) return problem.factor_H * (problem.factor_A * r) + problem.q;
  if (problem.is_sparse) return problem.sparse_W * r + problem.q;
  return problem.dense_W * r + problem.q;
}

LocalVector block_row_times(const FrictionProblem& problem, int contact, const Eigen::VectorXd& r) {
  const int d = problem.dimension;
  LocalVector result(d);
  if (problem.is_factored) {  // a whole A r: only for solvers that sweep it rarely
    const Eigen::VectorXd velocity = problem.factor_A * r;
    for (int k = 0; k < d; ++k) result(k) = problem.factor_H.row(contact * d + k).dot(velocity);
    return result;
  }
  if (!problem.is_sparse) {
    result.noalias() = problem.dense_W.middleRows(contact * d, d) * r;
    return result;
  }
  for (int k = 0; k < d; ++k) {
    double sum = 0.0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(problem.sparse_W,
                                                                        contact * d + k);
         it; ++it) {
      sum += it.value() * r(it.col());
    }
    result(k) = sum;
  }
  return result;
}

LocalMatrix diagonal_block(const FrictionProblem& problem, int contact) {
  const int d = problem.dimension;
  const int first = contact * d;
  if (problem.is_factored) {  // W_ii = H_i A_i: sparse rows of H times sparse columns of A
    LocalMatrix block(d, d);
    for (int k = 0; k < d; ++k)
      for (int c = 0; c < d; ++c)
        block(k, c) = problem.factor_H.row(first + k).dot(problem.factor_A.col(first + c));
    return block;
  }
  if (!problem.is_sparse) return problem.dense_W.block(first, first, d, d);
  LocalMatrix block = LocalMatrix::Zero(d, d);
  for (int k = 0; k < d; ++k) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(problem.sparse_W,
                                                                        first + k);
         it; ++it) {
      const auto col = it.col();
      if (col >= first && col < first + d) block(k, col - first) += it.value();
    }
  }
  return block;
}

std::vector<LocalMatrix> diagonal_blocks(const FrictionProblem& problem) {
  std::vector<LocalMatrix> blocks;
  blocks.reserve(static_cast<std::size_t>(problem.num_contacts()));
  for (int i = 0; i < problem.num_contacts(); ++i) blocks.push_back(diagonal_block(problem, i));
  return blocks;
}

FrictionProblem formed_delassus(const FrictionProblem& problem) {
  if (!problem.is_factored) return problem;
  Eigen::SparseMatrix<double, Eigen::RowMajor> W = problem.factor_H * problem.factor_A;
  W.makeCompressed();
  return FrictionProblem::sparse(problem.dimension, std::move(W), problem.q, problem.mu);
}

}  // namespace impactbench::solvers
