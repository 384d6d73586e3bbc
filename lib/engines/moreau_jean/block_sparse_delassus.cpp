#include "lib/engines/moreau_jean/block_sparse_delassus.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
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

using InverseZeros = BlockSparseWorkspace::InverseZeros;

// M⁻¹ restricted to each range, dense, with its zeros; false when an entry couples a range to
// another velocity.
bool restrict_inverse_mass(const Eigen::SparseMatrix<double>& inverse_mass, BlockLayout& layout) {
  const auto& ranges = layout.ranges;
  reserve_growing(layout.minv_offset, ranges.size() + 1);
  layout.minv_offset.assign(ranges.size() + 1, 0);
  for (std::size_t r = 0; r < ranges.size(); ++r)
    layout.minv_offset[r + 1] = layout.minv_offset[r] + ranges[r].size * ranges[r].size;
  reserve_growing(layout.minv, static_cast<std::size_t>(layout.minv_offset.back()));
  layout.minv.assign(static_cast<std::size_t>(layout.minv_offset.back()), 0.0);
  reserve_growing(layout.minv_zeros, ranges.size());
  layout.minv_zeros.resize(ranges.size());
  for (std::size_t r = 0; r < ranges.size(); ++r) {
    const Range& range = ranges[r];
    // Its zeros (InverseZeros), from the nonzero entries off the diagonal.
    bool diagonal = true;
    bool rotation_block_only = range.size == 6;
    for (int k = range.first; k < range.first + range.size; ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(inverse_mass, k); it; ++it) {
        const int row = static_cast<int>(it.row());
        if (row < range.first || row >= range.first + range.size) return false;
        const int local_row = row - range.first, local_column = k - range.first;
        layout.minv[static_cast<std::size_t>(layout.minv_offset[r] + local_column * range.size +
                                             local_row)] = it.value();
        if (local_row == local_column || it.value() == 0.0) continue;
        diagonal = false;
        if (local_row < 3 || local_column < 3) rotation_block_only = false;
      }
    layout.minv_zeros[r] = diagonal              ? InverseZeros::kOffDiagonal
                           : rotation_block_only ? InverseZeros::kOffTheRotationBlock
                                                 : InverseZeros::kNone;
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
    // By range, by insertion: a contact has a block or two (std::sort's set-up cost more).
    for (std::size_t k = first_block + 1; k < blocks.size(); ++k)
      for (std::size_t p = k; p > first_block && blocks[p].range < blocks[p - 1].range; --p)
        std::swap(blocks[p], blocks[p - 1]);
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

// H_ib (size × dim, column-major) = M⁻¹_b (size × size, column-major) J_ibᵀ, J_ib (dim × size,
// column-major): each entry a sum from +0 over c ascending. Terms with a zero of M⁻¹_b (`zeros`)
// are left out: such a product is ±0, and adding ±0 leaves a sum started at +0 as it is (it is
// never −0), so the sums keep every bit. `dim` and `size` ints or compile-time constants.
template <typename Dim, typename Size>
[[gnu::always_inline]] inline void compute_h(const double* minv_b, InverseZeros zeros,
                                             const double* j, Dim dim, Size size, double* h) {
  const auto sum = [&](int row, int col, int first, int last) __attribute__((always_inline)) {
    double total = 0.0;
    for (int c = first; c < last; ++c) total += minv_b[c * size + row] * j[c * dim + col];
    return total;
  };
  for (int col = 0; col < dim; ++col) {
    double* h_col = h + col * size;
    if (zeros == InverseZeros::kOffDiagonal) {
      for (int row = 0; row < size; ++row) h_col[row] = sum(row, col, row, row + 1);
    } else if (zeros == InverseZeros::kOffTheRotationBlock) {  // size 6
      for (int row = 0; row < 3; ++row) h_col[row] = sum(row, col, row, row + 1);
      for (int row = 3; row < 6; ++row) h_col[row] = sum(row, col, 3, 6);
    } else {
      for (int row = 0; row < size; ++row) h_col[row] = sum(row, col, 0, size);
    }
  }
}

// Sizes `out` for the layout's blocks, its storage kept (entries are not cleared: every one is
// written), so that write_factor_block fills it by index: block k's J_ib and then H_ib at twice
// its offset in the H storage (J_ib has as many entries as H_ib).
void size_factor_blocks(const BlockLayout& layout, int contacts, solvers::FactorBlocks& out) {
  const std::size_t count = layout.blocks.size();
  for (auto* column : {&out.first_velocity, &out.size, &out.offset}) {
    reserve_growing(*column, count);
    column->resize(count);
  }
  reserve_growing(out.contact_start, static_cast<std::size_t>(contacts) + 1);
  out.contact_start.resize(static_cast<std::size_t>(contacts) + 1);
  out.contact_start[0] = 0;
  reserve_growing(out.values, 2 * layout.h_storage.size());
  out.values.resize(2 * layout.h_storage.size());
}

// Block k of `out` (sized by size_factor_blocks): its range, J_ib and H_ib (computed).
template <typename Dim, typename Size>
[[gnu::always_inline]] inline void write_factor_block(const BlockLayout& layout, int k, Dim dim,
                                                      Size size, solvers::FactorBlocks& out) {
  const auto block = static_cast<std::size_t>(k);
  const BlockRef& b = layout.blocks[block];
  out.first_velocity[block] = layout.ranges[static_cast<std::size_t>(b.range)].first;
  out.size[block] = size;
  out.offset[block] = 2 * b.h_offset;
  double* values = &out.values[2 * static_cast<std::size_t>(b.h_offset)];
  const double* j = b.rows->data();
  const double* h = &layout.h_storage[static_cast<std::size_t>(b.h_offset)];
  const int entries = size * dim;
  for (int e = 0; e < entries; ++e) values[e] = j[e];
  for (int e = 0; e < entries; ++e) values[entries + e] = h[e];
}

// J (row-major) and M⁻¹Jᵀ (column-major) as their compressed arrays are written, entry by entry.
struct CompressedWriter {
  double* j_values;
  int* j_columns;
  int* j_row_start;
  double* h_values;
  int* h_rows;
  int* h_column_start;
  int j_count = 0;
  int h_count = 0;
};

// Contact i: H_ib on each of its blocks (and the blocks into `factor_blocks` unless null), then
// its rows of J (blocks in range order give ascending columns; zeros left out, as in the general
// assembly) and its columns of M⁻¹Jᵀ (H_ib's column ρ on each of its ranges, rows ascending).
// `rows` (= dim) and the block sizes are compile-time constants where they are a rigid body's
// contact's, so that the loops unroll; inlined, so that the counts stay in registers.
template <bool kSparse, typename Rows>
[[gnu::always_inline]] inline void assemble_contact(int i, Rows rows, BlockLayout& layout,
                                                    CompressedWriter& out,
                                                    solvers::FactorBlocks* factor_blocks) {
  using solvers::factor_blocks::with_block_size;
  const int first = layout.first_block(i), end = layout.end_block(i);
  for (int k = first; k < end; ++k) {
    const BlockRef& b = layout.blocks[static_cast<std::size_t>(k)];
    const double* minv_b =
        &layout
             .minv[static_cast<std::size_t>(layout.minv_offset[static_cast<std::size_t>(b.range)])];
    double* h = &layout.h_storage[static_cast<std::size_t>(b.h_offset)];
    with_block_size(
        layout.size_of(b), [&](auto size) __attribute__((always_inline)) {
          compute_h(minv_b, layout.minv_zeros[static_cast<std::size_t>(b.range)], b.rows->data(),
                    rows, size, h);
          if (factor_blocks != nullptr) write_factor_block(layout, k, rows, size, *factor_blocks);
        });
  }
  if (factor_blocks != nullptr) factor_blocks->contact_start[static_cast<std::size_t>(i) + 1] = end;
  if constexpr (!kSparse) return;
  for (int rho = 0; rho < rows; ++rho) {
    out.j_row_start[i * rows + rho] = out.j_count;
    out.h_column_start[i * rows + rho] = out.h_count;
    for (int k = first; k < end; ++k) {
      const BlockRef& b = layout.blocks[static_cast<std::size_t>(k)];
      const int range_first = layout.ranges[static_cast<std::size_t>(b.range)].first;
      with_block_size(
          layout.size_of(b), [&](auto size) __attribute__((always_inline)) {
            const double* j_row = b.rows->data() + rho;  // J_ib's row ρ: entries `rows` apart
            for (int col = 0; col < size; ++col) {
              const double value = j_row[col * rows];
              if (value == 0.0) continue;
              out.j_values[out.j_count] = value;
              out.j_columns[out.j_count++] = range_first + col;
            }
            const double* h = &layout.h_storage[static_cast<std::size_t>(b.h_offset + rho * size)];
            for (int row = 0; row < size; ++row) {
              out.h_values[out.h_count] = h[row];
              out.h_rows[out.h_count++] = range_first + row;
            }
          });
    }
  }
}

// assemble_contact for every contact in turn, a contact's rows (dim) a constant where they are
// a friction contact's, 2 or 3.
template <bool kSparse>
void assemble_each_contact(std::span<const model::Contact<double>> contacts, BlockLayout& layout,
                           CompressedWriter& out, solvers::FactorBlocks* factor_blocks) {
  const int m = static_cast<int>(contacts.size());
  solvers::factor_blocks::with_constant<2, 3>(
      layout.dim, [&](auto rows) __attribute__((always_inline)) {
        for (int i = 0; i < m; ++i) {
          model::prefetch_contact_storage(contacts, static_cast<std::size_t>(i));
          assemble_contact<kSparse>(i, rows, layout, out, factor_blocks);
        }
      });
}

// Contact by contact (assemble_contact), so that its blocks are read once. J and M⁻¹Jᵀ are
// written straight into their compressed storage, sized for every entry of H first (J has as
// many or fewer): the same arrays that inserting entry by entry and finalising gives, without a
// call per entry. Without them (null), only the factor blocks are written.
void assemble_jacobians(std::span<const model::Contact<double>> contacts, BlockLayout& layout,
                        Eigen::SparseMatrix<double, Eigen::RowMajor>* jacobian_out,
                        Eigen::SparseMatrix<double>* inverse_mass_jacobian_t_out,
                        solvers::FactorBlocks* factor_blocks) {
  const int m = static_cast<int>(contacts.size());
  const int dim = layout.dim;
  if (factor_blocks != nullptr) {
    size_factor_blocks(layout, m, *factor_blocks);
    factor_blocks->velocities = layout.nv;
  }
  if (jacobian_out == nullptr) {  // the blocks alone
    CompressedWriter none{};
    assemble_each_contact</*kSparse=*/false>(contacts, layout, none, factor_blocks);
    return;
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor>& jacobian = *jacobian_out;
  Eigen::SparseMatrix<double>& inverse_mass_jacobian_t = *inverse_mass_jacobian_t_out;
  const auto h_entries = static_cast<Eigen::Index>(layout.h_storage.size());
  jacobian.resize(m * dim, layout.nv);
  reserve_growing(jacobian, h_entries);
  jacobian.resizeNonZeros(h_entries);
  inverse_mass_jacobian_t.resize(layout.nv, m * dim);
  reserve_growing(inverse_mass_jacobian_t, h_entries);
  inverse_mass_jacobian_t.resizeNonZeros(h_entries);
  CompressedWriter out{jacobian.valuePtr(),
                       jacobian.innerIndexPtr(),
                       jacobian.outerIndexPtr(),
                       inverse_mass_jacobian_t.valuePtr(),
                       inverse_mass_jacobian_t.innerIndexPtr(),
                       inverse_mass_jacobian_t.outerIndexPtr()};
  assemble_each_contact</*kSparse=*/true>(contacts, layout, out, factor_blocks);
  out.j_row_start[m * dim] = out.j_count;
  out.h_column_start[m * dim] = out.h_count;
  jacobian.resizeNonZeros(out.j_count);
  inverse_mass_jacobian_t.resizeNonZeros(out.h_count);
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
                                    Eigen::SparseMatrix<double, Eigen::RowMajor>* jacobian,
                                    Eigen::SparseMatrix<double, Eigen::RowMajor>* W_out,
                                    Eigen::SparseMatrix<double>* inverse_mass_jacobian_t,
                                    solvers::FactorBlocks* blocks,
                                    BlockSparseWorkspace* workspace) {
  BlockSparseWorkspace own_workspace;
  BlockLayout& layout = workspace != nullptr ? *workspace : own_workspace;
  layout.nv = static_cast<int>(inverse_mass.cols());
  layout.dim = dim;
  if ((jacobian == nullptr) != (inverse_mass_jacobian_t == nullptr) ||
      (jacobian == nullptr && blocks == nullptr))
    throw std::invalid_argument(
        "assemble_block_sparse_delassus: J and M^-1 J^T are both given, or neither with blocks");
  // Every check comes before the first output is touched: a false leaves all outputs alone.
  if (!find_ranges(contacts, layout) || !restrict_inverse_mass(inverse_mass, layout) ||
      !collect_blocks(contacts, layout))
    return false;
  const int m = static_cast<int>(contacts.size());
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
