#pragma once
// W = J M⁻¹ Jᵀ and M⁻¹ Jᵀ assembled contact block by contact block: when the contacts' Jacobian
// blocks lie on disjoint velocity ranges (rigid bodies: one range per body) and M⁻¹ couples no
// range to another, W_ij = Σ_b J_ib M⁻¹_b J_jbᵀ over the ranges b that contacts i and j share,
// so W is formed directly in its block-sparse pattern, without general sparse products.
#include <span>
#include <vector>

#include <Eigen/SparseCore>

#include "lib/model/contact.hpp"
#include "solvers/friction/friction_problem.hpp"

namespace impactbench::engines::moreau_jean {

/// The assembly's working storage: the velocity ranges, M⁻¹ on each, every contact block with its
/// H_ib, and W's row blocks. A caller that assembles every step keeps one, so that its vectors
/// keep their capacity and a step in steady state allocates none of them.
struct BlockSparseWorkspace {
  struct Range {
    int first = 0;
    int size = 0;
  };
  // One contact's block on one range: its Jacobian rows J_ib (dim × size, column-major in the
  // contact) and H_ib = M⁻¹_b J_ibᵀ (size × dim).
  struct BlockRef {
    int contact = 0;
    int range = 0;
    const Eigen::MatrixXd* rows = nullptr;
    int h_offset = 0;  // into the flat H storage
  };
  struct Coupling {
    int contact;
    int own_block;    // index into blocks: contact i's block
    int other_block;  // index into blocks: contact j's block on the same range
  };

  int nv = 0;
  int dim = 0;
  std::vector<int> size_at;  // first velocity → the size of its range, 0 elsewhere
  std::vector<Range> ranges;
  std::vector<int> range_at;     // first velocity → range, −1 elsewhere
  std::vector<int> minv_offset;  // range → its dense M⁻¹_b (size × size, column-major) in minv
  std::vector<double> minv;
  /// Where M⁻¹_b is zero, so that H_ib's sums can leave those terms out
  /// (block_sparse_delassus.cpp).
  enum class InverseZeros : unsigned char {
    kNone,                ///< any entries
    kOffDiagonal,         ///< diagonal (a planar body: m, m, I)
    kOffTheRotationBlock  ///< 6 × 6, diagonal but for the lower-right 3 × 3 (a spatial body)
  };
  std::vector<InverseZeros> minv_zeros;  // range → its M⁻¹_b's zeros
  std::vector<BlockRef> blocks;    // a contact's blocks together, in the order of their ranges
  std::vector<int> contact_start;  // contact → its first block; one past the end last
  std::vector<double> h_storage;
  // W's row blocks: the blocks on each range, and one contact's couplings and rows.
  std::vector<int> range_start;
  std::vector<int> on_range;
  std::vector<int> fill;
  std::vector<Coupling> couplings;
  std::vector<int> partners;
  std::vector<double> w_rows;

  int size_of(const BlockRef& b) const { return ranges[static_cast<std::size_t>(b.range)].size; }
  int first_block(int contact) const { return contact_start[static_cast<std::size_t>(contact)]; }
  int end_block(int contact) const { return contact_start[static_cast<std::size_t>(contact) + 1]; }
};

/// Fills `jacobian` J (dim·m × nv, row-major), `inverse_mass_jacobian_t` (nv × dim·m) and, unless
/// null, `W` ((dim·m)², row-major) for the m `contacts` with `dim` = 1 + d rows each. Returns
/// false, leaving all outputs alone, when the blocks' ranges overlap, a contact has two blocks on
/// one range, or `inverse_mass` couples two ranges: callers then form the products in general.
/// Unless null, `blocks` receives J and M⁻¹Jᵀ by contact blocks (solvers::FactorBlocks); then
/// `jacobian` and `inverse_mass_jacobian_t` may both be null, and the blocks are the only form
/// of the factors. The outputs' storage is reused; `workspace` is the working storage (one made
/// for the call when null).
bool assemble_block_sparse_delassus(std::span<const model::Contact<double>> contacts, int dim,
                                    const Eigen::SparseMatrix<double>& inverse_mass,
                                    Eigen::SparseMatrix<double, Eigen::RowMajor>* jacobian,
                                    Eigen::SparseMatrix<double, Eigen::RowMajor>* W,
                                    Eigen::SparseMatrix<double>* inverse_mass_jacobian_t,
                                    solvers::FactorBlocks* blocks = nullptr,
                                    BlockSparseWorkspace* workspace = nullptr);

}  // namespace impactbench::engines::moreau_jean
