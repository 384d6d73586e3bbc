#pragma once
// Linear complementarity problem: find z with w = M z + q, 0 ≤ z ⊥ w ≥ 0.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace impactbench::solvers {

struct LcpProblem {
  /// Exactly one of the two representations is used: sparse when `is_sparse`.
  Eigen::MatrixXd dense_M;
  Eigen::SparseMatrix<double, Eigen::RowMajor> sparse_M;
  bool is_sparse = false;
  Eigen::VectorXd q;

  int size() const { return static_cast<int>(q.size()); }
  static LcpProblem dense(Eigen::MatrixXd M, Eigen::VectorXd q) {
    LcpProblem p;
    p.dense_M = std::move(M);
    p.q = std::move(q);
    return p;
  }
  static LcpProblem sparse(Eigen::SparseMatrix<double, Eigen::RowMajor> M, Eigen::VectorXd q) {
    LcpProblem p;
    p.sparse_M = std::move(M);
    p.is_sparse = true;
    p.q = std::move(q);
    return p;
  }
};

}  // namespace impactbench::solvers
