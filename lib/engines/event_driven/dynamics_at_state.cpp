#include "lib/engines/event_driven/dynamics_at_state.hpp"

#include <utility>

namespace impactbench::engines::event_driven {

MassFactor::MassFactor(const Eigen::SparseMatrix<double>& M) {
  diagonal_ = true;
  for (Eigen::Index k = 0; diagonal_ && k < M.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, k); it; ++it)
      if (it.row() != it.col() && it.value() != 0.0) diagonal_ = false;
  if (diagonal_)
    inverse_diagonal_ = M.diagonal().cwiseInverse();
  else
    ldlt_.compute(M);
}

DynamicsAtState::DynamicsAtState(const model::LagrangianSystem<double>& system,
                                 const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                 const Eigen::VectorXd& u)
    : DynamicsAtState(std::make_shared<const MassFactor>(system.mass_matrix(q)), system, q, v, u) {}

DynamicsAtState::DynamicsAtState(std::shared_ptr<const MassFactor> mass,
                                 const model::LagrangianSystem<double>& system,
                                 const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                 const Eigen::VectorXd& u)
    : mass_(std::move(mass)) {
  model::write_free_force(system, q, v, u, f_);
}

}  // namespace impactbench::engines::event_driven
