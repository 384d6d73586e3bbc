#pragma once
// Friction-contact problem in Delassus (FCLIB local) form: u = W r + q, per contact the local
// frame has the normal first, then 1 (planar) or 2 (spatial) tangential components; find r, u
// with K_μ ∋ r ⊥ u + g(u) ∈ K_μ*, g(u) = μ‖u_t‖ e_n (De Saxcé).
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace impactbench::solvers {

struct FrictionProblem {
  int dimension = 3;  ///< Components per contact: 2 planar (n, t), 3 spatial (n, t1, t2).
  /// Exactly one of the two representations is used: sparse (block-sparse) when `is_sparse`.
  Eigen::MatrixXd dense_W;
  Eigen::SparseMatrix<double, Eigen::RowMajor> sparse_W;
  bool is_sparse = false;
  Eigen::VectorXd q;   ///< dimension * contacts
  Eigen::VectorXd mu;  ///< contacts, each ≥ 0

  int num_contacts() const { return static_cast<int>(mu.size()); }
  int size() const { return static_cast<int>(q.size()); }
  static FrictionProblem dense(int dimension, Eigen::MatrixXd W, Eigen::VectorXd q,
                               Eigen::VectorXd mu) {
    FrictionProblem p;
    p.dimension = dimension;
    p.dense_W = std::move(W);
    p.q = std::move(q);
    p.mu = std::move(mu);
    return p;
  }
  static FrictionProblem sparse(int dimension, Eigen::SparseMatrix<double, Eigen::RowMajor> W,
                                Eigen::VectorXd q, Eigen::VectorXd mu) {
    FrictionProblem p;
    p.dimension = dimension;
    p.sparse_W = std::move(W);
    p.is_sparse = true;
    p.q = std::move(q);
    p.mu = std::move(mu);
    return p;
  }
};

}  // namespace impactbench::solvers
