#pragma once
// W = J M⁻¹ Jᵀ and M⁻¹ Jᵀ assembled contact block by contact block: when the contacts' Jacobian
// blocks lie on disjoint velocity ranges (rigid bodies: one range per body) and M⁻¹ couples no
// range to another, W_ij = Σ_b J_ib M⁻¹_b J_jbᵀ over the ranges b that contacts i and j share,
// so W is formed directly in its block-sparse pattern, without general sparse products.
#include <span>

#include <Eigen/SparseCore>

#include "lib/model/contact.hpp"
#include "solvers/friction/friction_problem.hpp"

namespace impactbench::engines::moreau_jean {

/// Fills `jacobian` J (dim·m × nv, row-major), `inverse_mass_jacobian_t` (nv × dim·m) and, unless
/// null, `W` ((dim·m)², row-major) for the m `contacts` with `dim` = 1 + d rows each. Returns
/// false, leaving all three alone, when the blocks' ranges overlap, a contact has two blocks on
/// one range, or `inverse_mass` couples two ranges: callers then form the products in general.
/// Unless null, `blocks` receives J and M⁻¹Jᵀ by contact blocks (solvers::FactorBlocks).
bool assemble_block_sparse_delassus(std::span<const model::Contact<double>> contacts, int dim,
                                    const Eigen::SparseMatrix<double>& inverse_mass,
                                    Eigen::SparseMatrix<double, Eigen::RowMajor>& jacobian,
                                    Eigen::SparseMatrix<double, Eigen::RowMajor>* W,
                                    Eigen::SparseMatrix<double>& inverse_mass_jacobian_t,
                                    solvers::FactorBlocks* blocks = nullptr);

}  // namespace impactbench::engines::moreau_jean
