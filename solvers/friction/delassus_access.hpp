#pragma once
// Block access to the Delassus matrix W of a FrictionProblem, dense, row-major sparse or
// factored, so that every solver sweeps contact by contact the same way.
#include <vector>

#include "solvers/friction/coulomb_cone.hpp"
#include "solvers/friction/friction_problem.hpp"

namespace impactbench::solvers {

namespace factor_blocks {
struct RigidContactBlocks;
}

/// u = W r + q.
CapacityVector contact_velocity(const FrictionProblem& problem, VectorView r);
/// The same into `out` (resized; not r itself), reusing its storage: the same bits. A factored
/// problem's A r, formed on the way, goes to `factored_velocity` when given (else to storage
/// kept per thread).
void write_contact_velocity(const FrictionProblem& problem, VectorView r, CapacityVector& out,
                            CapacityVector* factored_velocity = nullptr);

/// A r of a factored problem (W = H A): the velocity its impulses r give.
CapacityVector factored_velocity(const FrictionProblem& problem, VectorView r);
/// The same into `out` (resized; not r itself), reusing its storage. `rigid`: the factor blocks'
/// descriptions (factor_blocks::describe_rigid_contacts) when the caller keeps them; the same bits.
void write_factored_velocity(const FrictionProblem& problem, VectorView r, CapacityVector& out,
                             const std::vector<factor_blocks::RigidContactBlocks>* rigid = nullptr);

/// H w by factor blocks alone (of `dimension` rows per contact), into `out` (resized to the
/// contacts' rows; not `velocity` itself): the sums of the sparse H's product, to the bit.
void write_factor_rows_times(const FactorBlocks& blocks, int dimension, VectorView velocity,
                             CapacityVector& out,
                             const std::vector<factor_blocks::RigidContactBlocks>* rigid = nullptr);

/// H w and H x by factor blocks alone into `out_w` and `out_x` in one pass over the blocks (each
/// as write_factor_rows_times gives it, to the bit): a stepper needs both J v_free and J v_k.
void write_factor_rows_times(const FactorBlocks& blocks, int dimension, VectorView w,
                             CapacityVector& out_w, VectorView x, CapacityVector& out_x);

/// H w + q of a factored problem: u for the velocity w = A r.
CapacityVector factored_contact_velocity(const FrictionProblem& problem, VectorView velocity);
/// The same into `out` (resized; not `velocity` itself), reusing its storage; `rigid` as above.
void write_factored_contact_velocity(
    const FrictionProblem& problem, VectorView velocity, CapacityVector& out,
    const std::vector<factor_blocks::RigidContactBlocks>* rigid = nullptr);

/// (W r)_i: the rows of contact i times r.
LocalVector block_row_times(const FrictionProblem& problem, int contact, VectorView r);

/// W_ii: the diagonal block of contact i.
LocalMatrix diagonal_block(const FrictionProblem& problem, int contact);

/// All diagonal blocks, computed once per solve.
std::vector<LocalMatrix> diagonal_blocks(const FrictionProblem& problem);
/// The same into `blocks`, reusing its storage.
void diagonal_blocks(const FrictionProblem& problem, std::vector<LocalMatrix>& blocks);

/// factor_H and factor_A of a problem given by its factor blocks alone (the same entries, H's zeros
/// left out).
void sparse_factors_from_blocks(const FactorBlocks& blocks, int dimension,
                                Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                                Eigen::SparseMatrix<double>& A);

/// The same problem with W formed (a sparse W = H A for a factored problem; others unchanged).
FrictionProblem formed_delassus(const FrictionProblem& problem);

/// The components of contact i in a stacked vector.
template <typename Derived>
auto contact_part(Eigen::MatrixBase<Derived>& v, int contact, int dimension) {
  return v.segment(contact * dimension, dimension);
}
template <typename Derived>
auto contact_part(const Eigen::MatrixBase<Derived>& v, int contact, int dimension) {
  return v.segment(contact * dimension, dimension);
}

}  // namespace impactbench::solvers
