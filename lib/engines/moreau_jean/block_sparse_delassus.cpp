#include "lib/engines/moreau_jean/block_sparse_delassus.hpp"

#include <algorithm>
#include <vector>

#include <Eigen/Core>

#include "lib/model/contact_prefetch.hpp"
#include "lib/model/growing_capacity.hpp"
#include "solvers/friction/factor_blocks_kernels.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

using model::reserve_growing;

// What the stages below share: the ranges, M⁻¹ on each, every block with its H (the caller's
// workspace, or one made for the call).
using BlockLayout = BlockSparseWorkspace;
using Range = BlockSparseWorkspace::Range;
using BlockRef = BlockSparseWorkspace::BlockRef;
using Coupling = BlockSparseWorkspace::Coupling;

// The velocity ranges of the blocks, marked by their first velocity: disjoint, each with one
// size. False when they are not.
bool find_ranges(std::span<const model::Contact<double>> contacts, BlockLayout& layout) {
  const int nv = layout.nv;
  std::vector<int>& size_at = layout.size_at;
  size_at.assign(static_cast<std::size_t>(nv), 0);
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    model::prefetch_contact_storage(contacts, i);  // the first pass to reach them
    for (const auto& b : contacts[i].blocks) {
      const int size = static_cast<int>(b.rows.cols());
      if (b.first_velocity < 0 || size <= 0 || b.first_velocity + size > nv) return false;
      int& marked = size_at[static_cast<std::size_t>(b.first_velocity)];
      if (marked != 0 && marked != size) return false;
      marked = size;
    }
  }
  layout.range_at.assign(static_cast<std::size_t>(nv), -1);
  layout.ranges.clear();
  for (int v = 0; v < nv; ++v) {
    const int size = size_at[static_cast<std::size_t>(v)];
    if (size == 0) continue;
    const auto& ranges = layout.ranges;
    if (!ranges.empty() && ranges.back().first + ranges.back().size > v) return false;
    layout.range_at[static_cast<std::size_t>(v)] = static_cast<int>(ranges.size());
    layout.ranges.push_back({v, size});
  }
  return true;
}

// M⁻¹ restricted to each range, dense; false when an entry couples a range to another velocity.
bool restrict_inverse_mass(const Eigen::SparseMatrix<double>& inverse_mass, BlockLayout& layout) {
  const auto& ranges = layout.ranges;
  reserve_growing(layout.minv_offset, ranges.size() + 1);
  layout.minv_offset.assign(ranges.size() + 1, 0);
  for (std::size_t r = 0; r < ranges.size(); ++r)
    layout.minv_offset[r + 1] = layout.minv_offset[r] + ranges[r].size * ranges[r].size;
  reserve_growing(layout.minv, static_cast<std::size_t>(layout.minv_offset.back()));
  layout.minv.assign(static_cast<std::size_t>(layout.minv_offset.back()), 0.0);
  for (std::size_t r = 0; r < ranges.size(); ++r) {
    const Range& range = ranges[r];
    for (int k = range.first; k < range.first + range.size; ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(inverse_mass, k); it; ++it) {
        const int row = static_cast<int>(it.row());
        if (row < range.first || row >= range.first + range.size) return false;
        layout.minv[static_cast<std::size_t>(
            layout.minv_offset[r] + (k - range.first) * range.size + (row - range.first))] =
            it.value();
      }
  }
  return true;
}

// Every block, a contact's blocks in the order of their ranges, with room for its H; false when
// a block has the wrong row count or a contact has two blocks on one range.
bool collect_blocks(std::span<const model::Contact<double>> contacts, BlockLayout& layout) {
  const int m = static_cast<int>(contacts.size());
  auto& blocks = layout.blocks;
  blocks.clear();
  reserve_growing(layout.contact_start, static_cast<std::size_t>(m) + 1);
  layout.contact_start.assign(static_cast<std::size_t>(m) + 1, 0);
  for (int i = 0; i < m; ++i) {
    const std::size_t first_block = blocks.size();
    for (const auto& b : contacts[static_cast<std::size_t>(i)].blocks) {
      if (b.rows.rows() != layout.dim) return false;
      blocks.push_back(
          {i, layout.range_at[static_cast<std::size_t>(b.first_velocity)], &b.rows, 0});
    }
    std::sort(blocks.begin() + static_cast<std::ptrdiff_t>(first_block), blocks.end(),
              [](const BlockRef& a, const BlockRef& b) { return a.range < b.range; });
    for (std::size_t k = first_block + 1; k < blocks.size(); ++k)
      if (blocks[k].range == blocks[k - 1].range) return false;  // two blocks on one body
    layout.contact_start[static_cast<std::size_t>(i) + 1] = static_cast<int>(blocks.size());
  }
  std::size_t h_entries = 0;
  for (BlockRef& b : blocks) {
    b.h_offset = static_cast<int>(h_entries);
    h_entries += static_cast<std::size_t>(layout.size_of(b) * layout.dim);
  }
  reserve_growing(layout.h_storage, h_entries);
  layout.h_storage.resize(h_entries);
  return true;
}

// H_ib (size × dim, column-major) = M⁻¹_b (size × size, column-major) J_ibᵀ; a rigid body's
// size is a compile-time constant (factor_blocks::with_block_size), so the sums unroll.
void compute_h(const BlockRef& b, BlockLayout& layout) {
  const int dim = layout.dim;
  const double* minv_b =
      &layout.minv[static_cast<std::size_t>(layout.minv_offset[static_cast<std::size_t>(b.range)])];
  const double* j = b.rows->data();  // dim × size, column-major
  double* h = &layout.h_storage[static_cast<std::size_t>(b.h_offset)];
  solvers::factor_blocks::with_block_size(layout.size_of(b), [&](auto size) {
    for (int col = 0; col < dim; ++col)
      for (int row = 0; row < size; ++row) {
        double sum = 0.0;
        for (int c = 0; c < size; ++c) sum += minv_b[c * size + row] * j[c * dim + col];
        h[col * size + row] = sum;
      }
  });
}

// Contact i's blocks, J_ib then H_ib each, after the contacts before it.
void append_factor_blocks(const BlockLayout& layout, int i, solvers::FactorBlocks& out) {
  for (int k = layout.first_block(i); k < layout.end_block(i); ++k) {
    const BlockRef& b = layout.blocks[static_cast<std::size_t>(k)];
    const Range& range = layout.ranges[static_cast<std::size_t>(b.range)];
    const auto entries = static_cast<std::ptrdiff_t>(range.size * layout.dim);
    out.first_velocity.push_back(range.first);
    out.size.push_back(range.size);
    out.offset.push_back(static_cast<int>(out.values.size()));
    out.values.insert(out.values.end(), b.rows->data(), b.rows->data() + entries);
    const double* h = &layout.h_storage[static_cast<std::size_t>(b.h_offset)];
    out.values.insert(out.values.end(), h, h + entries);
  }
  out.contact_start.push_back(static_cast<int>(out.first_velocity.size()));
}

// Contact by contact, so that its blocks are read once: H_ib, then its rows of J (blocks in range
// order give ascending columns; zeros left out, as in the general assembly) and its columns of
// M⁻¹ Jᵀ (H_ib's column ρ on each of its ranges, rows ascending). Both are written straight into
// their compressed storage, sized for every entry of H first (J has as many or fewer): the same
// arrays that inserting entry by entry and finalising gives, without a call per entry.
void assemble_jacobians(std::span<const model::Contact<double>> contacts, BlockLayout& layout,
                        Eigen::SparseMatrix<double, Eigen::RowMajor>& jacobian,
                        Eigen::SparseMatrix<double>& inverse_mass_jacobian_t,
                        solvers::FactorBlocks* factor_blocks) {
  const int m = static_cast<int>(contacts.size());
  const int dim = layout.dim;
  const auto h_entries = static_cast<Eigen::Index>(layout.h_storage.size());
  jacobian.resize(m * dim, layout.nv);
  reserve_growing(jacobian, h_entries);
  jacobian.resizeNonZeros(h_entries);
  inverse_mass_jacobian_t.resize(layout.nv, m * dim);
  reserve_growing(inverse_mass_jacobian_t, h_entries);
  inverse_mass_jacobian_t.resizeNonZeros(h_entries);
  double* j_values = jacobian.valuePtr();
  int* j_columns = jacobian.innerIndexPtr();
  int* j_row_start = jacobian.outerIndexPtr();
  double* h_values = inverse_mass_jacobian_t.valuePtr();
  int* h_rows = inverse_mass_jacobian_t.innerIndexPtr();
  int* h_column_start = inverse_mass_jacobian_t.outerIndexPtr();
  int j_count = 0, h_count = 0;
  for (int i = 0; i < m; ++i) {
    model::prefetch_contact_storage(contacts, static_cast<std::size_t>(i));
    for (int k = layout.first_block(i); k < layout.end_block(i); ++k)
      compute_h(layout.blocks[static_cast<std::size_t>(k)], layout);
    if (factor_blocks != nullptr) append_factor_blocks(layout, i, *factor_blocks);
    for (int rho = 0; rho < dim; ++rho) {
      const int row_or_column = i * dim + rho;
      j_row_start[row_or_column] = j_count;
      h_column_start[row_or_column] = h_count;
      for (int k = layout.first_block(i); k < layout.end_block(i); ++k) {
        const BlockRef& b = layout.blocks[static_cast<std::size_t>(k)];
        const Range& range = layout.ranges[static_cast<std::size_t>(b.range)];
        for (int col = 0; col < range.size; ++col) {
          const double value = (*b.rows)(rho, col);
          if (value == 0.0) continue;
          j_values[j_count] = value;
          j_columns[j_count++] = range.first + col;
        }
        const double* h =
            &layout.h_storage[static_cast<std::size_t>(b.h_offset + rho * range.size)];
        for (int row = 0; row < range.size; ++row) {
          h_values[h_count] = h[row];
          h_rows[h_count++] = range.first + row;
        }
      }
    }
  }
  j_row_start[m * dim] = j_count;
  h_column_start[m * dim] = h_count;
  jacobian.resizeNonZeros(j_count);
  inverse_mass_jacobian_t.resizeNonZeros(h_count);
}

// W row block by row block: contact i meets every contact j sharing one of its ranges,
// W_ij = Σ_b J_ib H_jb.
class DelassusRows {
 public:
  explicit DelassusRows(BlockLayout& layout)
      : layout_(layout),
        range_start_(layout.range_start),
        on_range_(layout.on_range),
        couplings_(layout.couplings),
        partners_(layout.partners),
        w_rows_(layout.w_rows) {
    // The blocks on each range (counting sort).
    reserve_growing(range_start_, layout.ranges.size() + 1);
    range_start_.assign(layout.ranges.size() + 1, 0);
    for (const BlockRef& b : layout.blocks) ++range_start_[static_cast<std::size_t>(b.range) + 1];
    for (std::size_t r = 0; r < layout.ranges.size(); ++r) range_start_[r + 1] += range_start_[r];
    reserve_growing(on_range_, layout.blocks.size());
    on_range_.resize(layout.blocks.size());
    std::vector<int>& fill = layout.fill;
    reserve_growing(fill, range_start_.size() - 1);
    fill.assign(range_start_.begin(), range_start_.end() - 1);
    for (std::size_t k = 0; k < layout.blocks.size(); ++k)
      on_range_[static_cast<std::size_t>(
          fill[static_cast<std::size_t>(layout.blocks[k].range)]++)] = static_cast<int>(k);
  }

  void append_row_block(int i, Eigen::SparseMatrix<double, Eigen::RowMajor>& W) {
    find_couplings(i);
    accumulate();
    const int dim = layout_.dim;
    const std::size_t width = partners_.size() * static_cast<std::size_t>(dim);
    for (int rho = 0; rho < dim; ++rho) {
      W.startVec(i * dim + rho);
      for (std::size_t p = 0; p < partners_.size(); ++p)
        for (int col = 0; col < dim; ++col)
          W.insertBack(i * dim + rho, partners_[p] * dim + col) =
              w_rows_[static_cast<std::size_t>(rho) * width + p * static_cast<std::size_t>(dim) +
                      static_cast<std::size_t>(col)];
    }
  }

 private:
  // Every (own block, other block) pair of contact i on a shared range, by partner contact.
  void find_couplings(int i) {
    couplings_.clear();
    for (int k = layout_.first_block(i); k < layout_.end_block(i); ++k) {
      const int r = layout_.blocks[static_cast<std::size_t>(k)].range;
      for (int p = range_start_[static_cast<std::size_t>(r)];
           p < range_start_[static_cast<std::size_t>(r) + 1]; ++p) {
        const int other = on_range_[static_cast<std::size_t>(p)];
        couplings_.push_back({layout_.blocks[static_cast<std::size_t>(other)].contact, k, other});
      }
    }
    std::sort(couplings_.begin(), couplings_.end(),
              [](const Coupling& a, const Coupling& b) { return a.contact < b.contact; });
    partners_.clear();
    for (const Coupling& c : couplings_)
      if (partners_.empty() || partners_.back() != c.contact) partners_.push_back(c.contact);
  }

  // w_rows_ (dim × (dim · partners), row-major) = Σ over couplings of J_own H_other.
  void accumulate() {
    const int dim = layout_.dim;
    const std::size_t width = partners_.size() * static_cast<std::size_t>(dim);
    reserve_growing(w_rows_, static_cast<std::size_t>(dim) * width);
    w_rows_.assign(static_cast<std::size_t>(dim) * width, 0.0);
    std::size_t slot = 0;  // the partner of the current coupling
    for (const Coupling& c : couplings_) {
      while (partners_[slot] != c.contact) ++slot;
      const BlockRef& own = layout_.blocks[static_cast<std::size_t>(c.own_block)];
      const BlockRef& other = layout_.blocks[static_cast<std::size_t>(c.other_block)];
      const int size = layout_.size_of(own);
      const double* j_own = own.rows->data();  // dim × size, column-major
      const double* h_other =
          &layout_.h_storage[static_cast<std::size_t>(other.h_offset)];  // size × dim
      for (int rho = 0; rho < dim; ++rho)
        for (int col = 0; col < dim; ++col) {
          double sum = 0.0;
          for (int k = 0; k < size; ++k) sum += j_own[k * dim + rho] * h_other[col * size + k];
          w_rows_[static_cast<std::size_t>(rho) * width + slot * static_cast<std::size_t>(dim) +
                  static_cast<std::size_t>(col)] += sum;
        }
    }
  }

  const BlockLayout& layout_;
  std::vector<int>& range_start_;
  std::vector<int>& on_range_;
  std::vector<Coupling>& couplings_;
  std::vector<int>& partners_;
  std::vector<double>& w_rows_;
};

}  // namespace

bool assemble_block_sparse_delassus(std::span<const model::Contact<double>> contacts, int dim,
                                    const Eigen::SparseMatrix<double>& inverse_mass,
                                    Eigen::SparseMatrix<double, Eigen::RowMajor>& jacobian,
                                    Eigen::SparseMatrix<double, Eigen::RowMajor>* W_out,
                                    Eigen::SparseMatrix<double>& inverse_mass_jacobian_t,
                                    solvers::FactorBlocks* blocks,
                                    BlockSparseWorkspace* workspace) {
  BlockSparseWorkspace own_workspace;
  BlockLayout& layout = workspace != nullptr ? *workspace : own_workspace;
  layout.nv = static_cast<int>(inverse_mass.cols());
  layout.dim = dim;
  // Every check comes before the first output is touched: a false leaves all three alone.
  if (!find_ranges(contacts, layout) || !restrict_inverse_mass(inverse_mass, layout) ||
      !collect_blocks(contacts, layout))
    return false;
  const int m = static_cast<int>(contacts.size());
  if (blocks != nullptr) {
    blocks->clear();
    reserve_growing(blocks->contact_start, static_cast<std::size_t>(contacts.size()) + 1);
    blocks->contact_start.push_back(0);
    for (auto* column : {&blocks->first_velocity, &blocks->size, &blocks->offset})
      reserve_growing(*column, layout.blocks.size());
    reserve_growing(blocks->values, 2 * layout.h_storage.size());
  }
  assemble_jacobians(contacts, layout, jacobian, inverse_mass_jacobian_t, blocks);
  if (W_out == nullptr) return true;
  Eigen::SparseMatrix<double, Eigen::RowMajor>& W = *W_out;
  W.resize(m * dim, m * dim);
  reserve_growing(W, static_cast<Eigen::Index>(layout.blocks.size()) * 4 * dim * dim);
  DelassusRows rows(layout);
  for (int i = 0; i < m; ++i) rows.append_row_block(i, W);
  W.finalize();
  return true;
}

}  // namespace impactbench::engines::moreau_jean
