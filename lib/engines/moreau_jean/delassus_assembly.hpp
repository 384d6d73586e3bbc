#pragma once
// The one-step problem of Moreau–Jean in Delassus (FCLIB local) form, u = W r + q:
//   J    = [w_n W_t]ᵀ of the active contacts, (1 + d) rows per contact, assembled sparse from
//          the contacts' Jacobian blocks;
//   W    = J M⁻¹ Jᵀ, dense for small problems, sparse (block-sparse: contact i couples to j only
//          through a shared body) otherwise, so thousands of contacts never form a dense W, or,
//          at every size, kept as its factors J and M⁻¹Jᵀ for Gauss–Seidel, which then never
//          forms it;
//   q    = J v_free + [e_i min(ζ_n,i^k, 0), 0, ...] per contact (Newton restitution on the
//          normal, applied only to approaching contacts).
// Then v_{k+1} = v_free + M⁻¹ Jᵀ r.
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "lib/engines/moreau_jean/block_sparse_delassus.hpp"
#include "lib/model/contact.hpp"
#include "solvers/common/capacity_vector.hpp"
#include "solvers/friction/friction_problem.hpp"

namespace impactbench::engines::moreau_jean {

struct DelassusSystem {
  /// J, (1+d)m × nv, and M⁻¹ Jᵀ, nv × (1+d)m; empty when the problem is factored (they are its
  /// factors then: problem.factor_H and problem.factor_A, or its factor blocks alone).
  Eigen::SparseMatrix<double, Eigen::RowMajor> jacobian;
  Eigen::SparseMatrix<double> inverse_mass_jacobian_t;
  solvers::FrictionProblem problem;
  /// The assembly's working storage, kept with the system for the next assembly into it.
  BlockSparseWorkspace workspace;
  solvers::CapacityVector zeta_start;  ///< J v_k, for the restitution term (kept capacity)

  /// M⁻¹ Jᵀ r wherever M⁻¹ Jᵀ is kept, into `out` (its storage kept): a product into zeros, as
  /// Eigen forms one it returns (the factor blocks' product gives the same bits).
  void write_impulse_velocity(solvers::VectorView r, solvers::CapacityVector& out) const;
};

/// Contact Jacobian J of `contacts` (each with tangent dimension d), (1 + d)·m × nv.
Eigen::SparseMatrix<double, Eigen::RowMajor> assemble_contact_jacobian(
    std::span<const model::Contact<double>> contacts, int nv, int tangent_dim);

/// Builds the problem into `out`, reusing the storage of the problem assembled into it before
/// (a caller that keeps `out` from step to step allocates nothing once it has grown).
/// `velocity_start` is v_k (for the restitution term), `free_velocity` v_free; the problem is
/// factored (W = J · M⁻¹Jᵀ not formed) when `factored` (for a solver that sweeps the factors),
/// whatever its size; else dense when it has at most `dense_max_rows` rows, sparse beyond. A
/// factored problem whose contacts the block assembly applies to is given by its factor blocks
/// alone (FactorBlocks), without the sparse J and M⁻¹Jᵀ, so that its storage does not depend on
/// the number of contacts beyond its capacity.
void assemble_delassus(std::span<const model::Contact<double>> contacts, int tangent_dim,
                       const Eigen::SparseMatrix<double>& inverse_mass,
                       const Eigen::VectorXd& velocity_start, const Eigen::VectorXd& free_velocity,
                       int dense_max_rows, bool factored, DelassusSystem& out);

/// The same into a new system.
DelassusSystem assemble_delassus(std::span<const model::Contact<double>> contacts, int tangent_dim,
                                 const Eigen::SparseMatrix<double>& inverse_mass,
                                 const Eigen::VectorXd& velocity_start,
                                 const Eigen::VectorXd& free_velocity, int dense_max_rows,
                                 bool factored = false);

}  // namespace impactbench::engines::moreau_jean
