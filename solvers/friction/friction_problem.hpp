#pragma once
// Friction-contact problem in Delassus (FCLIB local) form: u = W r + q, per contact the local
// frame has the normal first, then 1 (planar) or 2 (spatial) tangential components; find r, u
// with K_μ ∋ r ⊥ u + g(u) ∈ K_μ*, g(u) = μ‖u_t‖ e_n (De Saxcé).
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solvers/common/capacity_vector.hpp"

namespace impactbench::solvers {

/// The factors of a factored problem contact by contact, where the assembly knows their block
/// structure (rigid bodies): each contact's blocks on disjoint velocity ranges, in ascending
/// order, each block its rows of H (dimension × size, column-major) and then its columns of A
/// (size × dimension, column-major), stored contact after contact so that a Gauss–Seidel sweep
/// reads them in order and the velocity A r by range. The same entries as factor_H and factor_A
/// (with H's zeros). A problem may give its factors by blocks only, with factor_H and factor_A
/// empty (0 × 0), as the time stepper's assembly does: everything that would read them reads the
/// blocks then, and formed_delassus() forms W from the blocks.
struct FactorBlocks {
  std::vector<int> contact_start;   ///< contact → its first block; one past the last at the end
  std::vector<int> first_velocity;  ///< block → the first velocity of its range
  std::vector<int> size;            ///< block → the size of its range
  std::vector<int> offset;          ///< block → its H entries in values, A's right after them
  std::vector<double> values;
  int velocities = 0;  ///< nv: the size of the velocity A r

  bool empty() const { return contact_start.empty(); }
  /// The contacts whose blocks are listed.
  int contacts() const { return empty() ? 0 : static_cast<int>(contact_start.size()) - 1; }
  void clear() {
    velocities = 0;
    contact_start.clear();
    first_velocity.clear();
    size.clear();
    offset.clear();
    values.clear();
  }
};

struct FrictionProblem {
  int dimension = 3;  ///< Components per contact: 2 planar (n, t), 3 spatial (n, t1, t2).
  /// Exactly one of the three representations is used: sparse (block-sparse) when `is_sparse`,
  /// factored when `is_factored`, else dense.
  Eigen::MatrixXd dense_W;
  Eigen::SparseMatrix<double, Eigen::RowMajor> sparse_W;
  bool is_sparse = false;
  /// W = H A kept in its factors and never formed (the time stepper's H = J, A = M⁻¹Jᵀ, so
  /// W = J M⁻¹ Jᵀ): H is n × nv row-major, A nv × n. Gauss–Seidel sweeps it through the
  /// velocity A r (as the impulse-based engines do); solvers that need W entry by entry are
  /// given formed_delassus() of it (friction_solvers.cpp).
  Eigen::SparseMatrix<double, Eigen::RowMajor> factor_H;
  Eigen::SparseMatrix<double> factor_A;
  FactorBlocks factor_blocks;  ///< optional: the same factors by contact blocks
  bool is_factored = false;
  // With kept capacity: a time stepper that assembles into the same problem at every step
  // allocates nothing for them once it has met its largest active count.
  CapacityVector q;   ///< dimension * contacts
  CapacityVector mu;  ///< contacts, each ≥ 0

  FrictionProblem() = default;
  FrictionProblem(const FrictionProblem&) = default;
  FrictionProblem& operator=(const FrictionProblem&) = default;
  // Eigen 3.4's SparseMatrix has no move operations (std::move copies it): moves swap.
  FrictionProblem(FrictionProblem&& other) noexcept { swap(other); }
  FrictionProblem& operator=(FrictionProblem&& other) noexcept {
    swap(other);
    return *this;
  }
  ~FrictionProblem() = default;
  void swap(FrictionProblem& other) noexcept {
    std::swap(dimension, other.dimension);
    dense_W.swap(other.dense_W);
    sparse_W.swap(other.sparse_W);
    std::swap(is_sparse, other.is_sparse);
    factor_H.swap(other.factor_H);
    factor_A.swap(other.factor_A);
    std::swap(factor_blocks, other.factor_blocks);
    std::swap(is_factored, other.is_factored);
    q.swap(other.q);
    mu.swap(other.mu);
  }

  int num_contacts() const { return static_cast<int>(mu.size()); }
  /// A factored problem given by its factor blocks alone, without factor_H and factor_A.
  bool factored_by_blocks_only() const {
    return is_factored && !factor_blocks.empty() && factor_H.size() == 0 && factor_A.size() == 0;
  }
  /// nv of a factored problem: the size of the velocity A r.
  Eigen::Index factored_velocities() const {
    return factor_blocks.empty() ? factor_A.rows() : factor_blocks.velocities;
  }
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
  /// H and A are taken over (swapped in, not copied).
  static FrictionProblem factored(int dimension, Eigen::SparseMatrix<double, Eigen::RowMajor>&& H,
                                  Eigen::SparseMatrix<double>&& A, Eigen::VectorXd q,
                                  Eigen::VectorXd mu) {
    FrictionProblem p;
    p.dimension = dimension;
    p.factor_H.swap(H);
    p.factor_A.swap(A);
    p.is_factored = true;
    p.q = std::move(q);
    p.mu = std::move(mu);
    return p;
  }
  /// W is taken over (swapped in, not copied).
  static FrictionProblem sparse(int dimension, Eigen::SparseMatrix<double, Eigen::RowMajor>&& W,
                                Eigen::VectorXd q, Eigen::VectorXd mu) {
    FrictionProblem p;
    p.dimension = dimension;
    p.sparse_W.swap(W);
    p.is_sparse = true;
    p.q = std::move(q);
    p.mu = std::move(mu);
    return p;
  }
};

}  // namespace impactbench::solvers
