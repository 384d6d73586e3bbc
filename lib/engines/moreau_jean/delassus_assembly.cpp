#include "lib/engines/moreau_jean/delassus_assembly.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "lib/engines/moreau_jean/block_sparse_delassus.hpp"

namespace impactbench::engines::moreau_jean {

Eigen::SparseMatrix<double, Eigen::RowMajor> assemble_contact_jacobian(
    std::span<const model::Contact<double>> contacts, int nv, int tangent_dim) {
  const int dim = 1 + tangent_dim;
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const int row0 = static_cast<int>(i) * dim;
    for (const auto& block : contacts[i].blocks) {
      if (block.rows.rows() != dim || block.first_velocity < 0 ||
          block.first_velocity + block.rows.cols() > nv)
        throw std::invalid_argument("contact '" + contacts[i].name +
                                    "' has a Jacobian block of the wrong size or range");
      for (int c = 0; c < block.rows.cols(); ++c)
        for (int r = 0; r < dim; ++r)
          if (block.rows(r, c) != 0.0)
            triplets.emplace_back(row0 + r, block.first_velocity + c, block.rows(r, c));
    }
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> J(static_cast<int>(contacts.size()) * dim, nv);
  J.setFromTriplets(triplets.begin(), triplets.end());  // sums blocks on the same body
  return J;
}

DelassusSystem assemble_delassus(std::span<const model::Contact<double>> contacts, int tangent_dim,
                                 const Eigen::SparseMatrix<double>& inverse_mass,
                                 const Eigen::VectorXd& velocity_start,
                                 const Eigen::VectorXd& free_velocity, int dense_max_rows,
                                 bool factored, solvers::FactorBlocks* block_storage) {
  const int nv = static_cast<int>(free_velocity.size());
  const int dim = 1 + tangent_dim;
  const int m = static_cast<int>(contacts.size());

  DelassusSystem out;
  const bool dense = m * dim <= dense_max_rows;
  const bool form_W = dense || !factored;
  Eigen::SparseMatrix<double, Eigen::RowMajor> W;
  solvers::FactorBlocks own_blocks;  // the factors by contact blocks, for a factored problem
  solvers::FactorBlocks& blocks = block_storage != nullptr ? *block_storage : own_blocks;
  if (!assemble_block_sparse_delassus(contacts, dim, inverse_mass, out.jacobian,
                                      form_W ? &W : nullptr, out.inverse_mass_jacobian_t,
                                      form_W ? nullptr : &blocks)) {
    blocks.clear();
    out.jacobian = assemble_contact_jacobian(contacts, nv, tangent_dim);
    out.inverse_mass_jacobian_t = inverse_mass * out.jacobian.transpose();
    if (form_W) W = out.jacobian * out.inverse_mass_jacobian_t;
  }

  Eigen::VectorXd q = out.jacobian * free_velocity;
  const Eigen::VectorXd zeta_start = out.jacobian * velocity_start;
  Eigen::VectorXd mu(m);
  for (int i = 0; i < m; ++i) {
    q(i * dim) += contacts[i].restitution * std::min(zeta_start(i * dim), 0.0);
    mu(i) = contacts[i].friction;
  }

  if (dense) {
    out.problem =
        solvers::FrictionProblem::dense(dim, Eigen::MatrixXd(W), std::move(q), std::move(mu));
  } else if (!form_W) {
    // The factors move into the problem (inverse_mass_jacobian() finds M⁻¹Jᵀ there).
    out.problem = solvers::FrictionProblem::factored(dim, std::move(out.jacobian),
                                                     std::move(out.inverse_mass_jacobian_t),
                                                     std::move(q), std::move(mu));
    std::swap(out.problem.factor_blocks, blocks);  // the caller's storage, lent
  } else {
    W.makeCompressed();
    out.problem = solvers::FrictionProblem::sparse(dim, std::move(W), std::move(q), std::move(mu));
  }
  return out;
}

}  // namespace impactbench::engines::moreau_jean
