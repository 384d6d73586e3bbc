#include "lib/engines/moreau_jean/delassus_assembly.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "lib/engines/moreau_jean/block_sparse_delassus.hpp"
#include "solvers/friction/delassus_access.hpp"

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
        // The time stepper's contacts may be unnamed (lagrangian_system.hpp): the key as well.
        throw std::invalid_argument(
            "contact " + std::to_string(i) +
            (contacts[i].name.empty() ? "" : " '" + contacts[i].name + "'") + " (bodies " +
            std::to_string(contacts[i].key.body_a) + " and " +
            std::to_string(contacts[i].key.body_b) +
            ") has a Jacobian block of the wrong size or range");
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

void assemble_delassus(std::span<const model::Contact<double>> contacts, int tangent_dim,
                       const Eigen::SparseMatrix<double>& inverse_mass,
                       const Eigen::VectorXd& velocity_start, const Eigen::VectorXd& free_velocity,
                       int dense_max_rows, bool factored, DelassusSystem& out) {
  const int nv = static_cast<int>(free_velocity.size());
  const int dim = 1 + tangent_dim;
  const int m = static_cast<int>(contacts.size());
  solvers::FrictionProblem& problem = out.problem;
  // The factors lent to the previous problem come back, with their storage.
  if (problem.is_factored) {
    out.jacobian.swap(problem.factor_H);
    out.inverse_mass_jacobian_t.swap(problem.factor_A);
  }

  // A solver that sweeps the factors gets them at every size: a dense row of W costs O(m) per
  // contact and sweep, the factors' blocks O(1), and forming W costs more than either (callgrind,
  // nsgs: 1 to 120 contacts, no size at which the dense form took fewer instructions).
  const bool dense = !factored && m * dim <= dense_max_rows;
  const bool form_W = !factored;
  // W is formed in the problem's sparse storage (a dense problem copies it out).
  Eigen::SparseMatrix<double, Eigen::RowMajor>& W = problem.sparse_W;
  // The factors by contact blocks: written over by a factored assembly (their storage kept),
  // cleared for a formed W (which has none) and where the block assembly does not apply.
  solvers::FactorBlocks& blocks = problem.factor_blocks;
  if (form_W) blocks.clear();
  // A factored problem is given by its blocks alone where the block assembly applies: J and
  // M⁻¹Jᵀ would be sparse matrices whose index arrays Eigen allocates anew whenever the number of
  // contacts changes (at almost every step of a pile whose contacts come and go).
  const bool blocks_only = !form_W;
  const bool by_blocks = assemble_block_sparse_delassus(
      contacts, dim, inverse_mass, blocks_only ? nullptr : &out.jacobian, form_W ? &W : nullptr,
      blocks_only ? nullptr : &out.inverse_mass_jacobian_t, form_W ? nullptr : &blocks,
      &out.workspace);
  if (!by_blocks) {
    blocks.clear();
    out.jacobian = assemble_contact_jacobian(contacts, nv, tangent_dim);
    out.inverse_mass_jacobian_t = inverse_mass * out.jacobian.transpose();
    if (form_W) W = out.jacobian * out.inverse_mass_jacobian_t;
  } else if (blocks_only) {
    // Left from an assembly of another form into this system (emptied once: resize allocates).
    if (out.jacobian.size() != 0) out.jacobian.resize(0, 0);
    if (out.inverse_mass_jacobian_t.size() != 0) out.inverse_mass_jacobian_t.resize(0, 0);
  }

  // Into kept storage (a product into zeros, as Eigen forms one it returns: the same bits, and
  // the factor blocks' product sums the same terms in the same order).
  solvers::CapacityVector& zeta_start = out.zeta_start;
  if (by_blocks && blocks_only) {
    solvers::write_factor_rows_times(blocks, dim, free_velocity, problem.q, velocity_start,
                                     zeta_start);
  } else {
    problem.q.assign_noalias(out.jacobian * free_velocity);
    zeta_start.assign_noalias(out.jacobian * velocity_start);
  }
  problem.mu.resize(m);
  for (int i = 0; i < m; ++i) {
    problem.q(i * dim) += contacts[i].restitution * std::min(zeta_start(i * dim), 0.0);
    problem.mu(i) = contacts[i].friction;
  }

  problem.dimension = dim;
  problem.is_sparse = !dense && form_W;
  problem.is_factored = !form_W;
  if (dense) {
    problem.dense_W = W;
    W.resize(0, 0);
  } else {
    problem.dense_W.resize(0, 0);
  }
  if (problem.is_sparse) {
    W.makeCompressed();
  } else if (problem.is_factored) {
    // The factors are lent to the problem (empty when its blocks alone are its factors).
    problem.factor_H.swap(out.jacobian);
    problem.factor_A.swap(out.inverse_mass_jacobian_t);
  }
}

void DelassusSystem::write_impulse_velocity(solvers::VectorView r,
                                            solvers::CapacityVector& out) const {
  if (problem.is_factored)
    solvers::write_factored_velocity(problem, r, out);
  else
    out.assign_noalias(inverse_mass_jacobian_t * r);
}

DelassusSystem assemble_delassus(std::span<const model::Contact<double>> contacts, int tangent_dim,
                                 const Eigen::SparseMatrix<double>& inverse_mass,
                                 const Eigen::VectorXd& velocity_start,
                                 const Eigen::VectorXd& free_velocity, int dense_max_rows,
                                 bool factored) {
  DelassusSystem out;
  assemble_delassus(contacts, tangent_dim, inverse_mass, velocity_start, free_velocity,
                    dense_max_rows, factored, out);
  return out;
}

}  // namespace impactbench::engines::moreau_jean
