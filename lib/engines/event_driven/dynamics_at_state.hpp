#pragma once
// M(q) factorised and the free generalized force f = S u − H at one state: what the flow, the
// impact maps and the mode decisions solve with.
#include <memory>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include "lib/model/lagrangian_system.hpp"

namespace impactbench::engines::event_driven {

/// M⁻¹ by a factorisation of M.
///
/// A diagonal M (free planar bodies) is inverted entry by entry instead of by a sparse LDLT,
/// whose ordering and symbolic analysis dominated a right-hand side of free flight; the
/// quotients are the LDLT's to the bit (it solves a diagonal system as (1/d_i) · b_i too).
class MassFactor {
 public:
  explicit MassFactor(const Eigen::SparseMatrix<double>& M);
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const {
    if (diagonal_) return inverse_diagonal_.asDiagonal() * rhs;
    return ldlt_.solve(rhs);
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const {
    if (diagonal_) return inverse_diagonal_.asDiagonal() * rhs;
    return ldlt_.solve(rhs);
  }
  /// M⁻¹ rhs into out (size nv), without a temporary.
  void solve(const Eigen::VectorXd& rhs, Eigen::Ref<Eigen::VectorXd> out) const {
    if (diagonal_)
      out = inverse_diagonal_.asDiagonal() * rhs;
    else
      out = ldlt_.solve(rhs);
  }
  /// M⁻¹ rhs into out (resized), in its storage.
  void solve(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& out) const {
    if (diagonal_)
      out = inverse_diagonal_.asDiagonal() * rhs;
    else
      out = ldlt_.solve(rhs);
  }

 private:
  bool diagonal_ = false;
  Eigen::VectorXd inverse_diagonal_;  // 1 / M_ii when diagonal_
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
};

/// Factorised M(q) and free generalized force f = S u − H at one state.
class DynamicsAtState {
 public:
  /// Factorises M(q).
  DynamicsAtState(const model::LagrangianSystem<double>& system, const Eigen::VectorXd& q,
                  const Eigen::VectorXd& v, const Eigen::VectorXd& u);
  /// With `mass`, the factor of an M that does not depend on q
  /// (LagrangianSystem::mass_matrix_is_constant), shared instead of factorised again.
  DynamicsAtState(std::shared_ptr<const MassFactor> mass,
                  const model::LagrangianSystem<double>& system, const Eigen::VectorXd& q,
                  const Eigen::VectorXd& v, const Eigen::VectorXd& u);
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const { return mass_->solve(rhs); }
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const { return mass_->solve(rhs); }
  void solve(const Eigen::VectorXd& rhs, Eigen::Ref<Eigen::VectorXd> out) const {
    mass_->solve(rhs, out);
  }
  void solve(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& out) const { mass_->solve(rhs, out); }
  const Eigen::VectorXd& free_force() const { return f_; }
  int nv() const { return static_cast<int>(f_.size()); }

 private:
  std::shared_ptr<const MassFactor> mass_;
  Eigen::VectorXd f_;
};

}  // namespace impactbench::engines::event_driven
