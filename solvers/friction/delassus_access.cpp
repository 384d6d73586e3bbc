#include "solvers/friction/delassus_access.hpp"

namespace impactbench::solvers {

Eigen::VectorXd contact_velocity(const FrictionProblem& problem, const Eigen::VectorXd& r) {
  if (problem.is_sparse) return problem.sparse_W * r + problem.q;
  return problem.dense_W * r + problem.q;
}

LocalVector block_row_times(const FrictionProblem& problem, int contact, const Eigen::VectorXd& r) {
  const int d = problem.dimension;
  LocalVector result(d);
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

}  // namespace impactbench::solvers
