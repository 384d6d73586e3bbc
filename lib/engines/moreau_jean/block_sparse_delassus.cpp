#include "lib/engines/moreau_jean/block_sparse_delassus.hpp"

#include <algorithm>
#include <vector>

#include <Eigen/Core>

namespace impactbench::engines::moreau_jean {
namespace {

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

}  // namespace

bool assemble_block_sparse_delassus(std::span<const model::Contact<double>> contacts, int dim,
                                    const Eigen::SparseMatrix<double>& inverse_mass,
                                    Eigen::SparseMatrix<double, Eigen::RowMajor>& jacobian,
                                    Eigen::SparseMatrix<double, Eigen::RowMajor>* W_out,
                                    Eigen::SparseMatrix<double>& inverse_mass_jacobian_t) {
  const int nv = static_cast<int>(inverse_mass.cols());
  const int m = static_cast<int>(contacts.size());

  // The velocity ranges of the blocks, marked by their first velocity: disjoint, each with one
  // size.
  std::vector<int> size_at(static_cast<std::size_t>(nv), 0);
  for (const auto& c : contacts)
    for (const auto& b : c.blocks) {
      const int size = static_cast<int>(b.rows.cols());
      if (b.first_velocity < 0 || size <= 0 || b.first_velocity + size > nv) return false;
      int& marked = size_at[static_cast<std::size_t>(b.first_velocity)];
      if (marked != 0 && marked != size) return false;
      marked = size;
    }
  std::vector<Range> ranges;
  std::vector<int> range_at(static_cast<std::size_t>(nv), -1);  // first velocity → range
  for (int v = 0; v < nv; ++v) {
    const int size = size_at[static_cast<std::size_t>(v)];
    if (size == 0) continue;
    if (!ranges.empty() && ranges.back().first + ranges.back().size > v) return false;
    range_at[static_cast<std::size_t>(v)] = static_cast<int>(ranges.size());
    ranges.push_back({v, size});
  }

  // M⁻¹ restricted to each range, dense; any entry coupling a range to another velocity → no.
  std::vector<int> minv_offset(ranges.size() + 1, 0);
  for (std::size_t r = 0; r < ranges.size(); ++r)
    minv_offset[r + 1] = minv_offset[r] + ranges[r].size * ranges[r].size;
  std::vector<double> minv(static_cast<std::size_t>(minv_offset.back()), 0.0);
  for (std::size_t r = 0; r < ranges.size(); ++r) {
    const Range& range = ranges[r];
    for (int k = range.first; k < range.first + range.size; ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(inverse_mass, k); it; ++it) {
        const int row = static_cast<int>(it.row());
        if (row < range.first || row >= range.first + range.size) return false;
        minv[static_cast<std::size_t>(minv_offset[r] + (k - range.first) * range.size +
                                      (row - range.first))] = it.value();
      }
  }

  // Every block with its H = M⁻¹_b J_ibᵀ; a contact's blocks in the order of their ranges.
  std::vector<int> contact_start(static_cast<std::size_t>(m) + 1, 0);
  std::vector<BlockRef> blocks;
  std::vector<double> h_storage;
  for (int i = 0; i < m; ++i) {
    const std::size_t first_block = blocks.size();
    for (const auto& b : contacts[static_cast<std::size_t>(i)].blocks) {
      if (b.rows.rows() != dim) return false;
      blocks.push_back({i, range_at[static_cast<std::size_t>(b.first_velocity)], &b.rows, 0});
    }
    std::sort(blocks.begin() + static_cast<std::ptrdiff_t>(first_block), blocks.end(),
              [](const BlockRef& a, const BlockRef& b) { return a.range < b.range; });
    for (std::size_t k = first_block + 1; k < blocks.size(); ++k)
      if (blocks[k].range == blocks[k - 1].range) return false;  // two blocks on one body
    contact_start[static_cast<std::size_t>(i) + 1] = static_cast<int>(blocks.size());
  }
  std::size_t h_entries = 0;
  for (BlockRef& b : blocks) {
    b.h_offset = static_cast<int>(h_entries);
    h_entries += static_cast<std::size_t>(ranges[static_cast<std::size_t>(b.range)].size * dim);
  }
  h_storage.resize(h_entries);
  const auto h_of = [&](const BlockRef& b) {
    const int size = ranges[static_cast<std::size_t>(b.range)].size;
    return Eigen::Map<const Eigen::MatrixXd>(&h_storage[static_cast<std::size_t>(b.h_offset)], size,
                                             dim);
  };

  // Contact by contact, so that its blocks are read once: H_ib, then its rows of J (blocks in
  // range order give ascending columns; zeros left out, as in the general assembly) and its
  // columns of M⁻¹ Jᵀ (H_ib's column ρ on each of its ranges, rows ascending).
  jacobian.resize(m * dim, nv);
  jacobian.reserve(static_cast<Eigen::Index>(h_entries));
  inverse_mass_jacobian_t.resize(nv, m * dim);
  inverse_mass_jacobian_t.reserve(static_cast<Eigen::Index>(h_entries));
  for (int i = 0; i < m; ++i) {
    for (int k = contact_start[i]; k < contact_start[i + 1]; ++k) {
      const BlockRef& b = blocks[static_cast<std::size_t>(k)];
      const int size = ranges[static_cast<std::size_t>(b.range)].size;
      // H (size × dim, column-major) = M⁻¹_b (size × size, column-major) J_ibᵀ.
      const double* minv_b =
          &minv[static_cast<std::size_t>(minv_offset[static_cast<std::size_t>(b.range)])];
      const double* j = b.rows->data();  // dim × size, column-major
      double* h = &h_storage[static_cast<std::size_t>(b.h_offset)];
      for (int col = 0; col < dim; ++col)
        for (int row = 0; row < size; ++row) {
          double sum = 0.0;
          for (int c = 0; c < size; ++c) sum += minv_b[c * size + row] * j[c * dim + col];
          h[col * size + row] = sum;
        }
    }
    for (int rho = 0; rho < dim; ++rho) {
      const int row_or_column = i * dim + rho;
      jacobian.startVec(row_or_column);
      inverse_mass_jacobian_t.startVec(row_or_column);
      for (int k = contact_start[i]; k < contact_start[i + 1]; ++k) {
        const BlockRef& b = blocks[static_cast<std::size_t>(k)];
        const Range& range = ranges[static_cast<std::size_t>(b.range)];
        for (int col = 0; col < range.size; ++col)
          if ((*b.rows)(rho, col) != 0.0)
            jacobian.insertBack(row_or_column, range.first + col) = (*b.rows)(rho, col);
        const auto h = h_of(b);
        for (int row = 0; row < range.size; ++row)
          inverse_mass_jacobian_t.insertBack(range.first + row, row_or_column) = h(row, rho);
      }
    }
  }
  jacobian.finalize();
  inverse_mass_jacobian_t.finalize();
  if (W_out == nullptr) return true;
  Eigen::SparseMatrix<double, Eigen::RowMajor>& W = *W_out;

  // The blocks on each range (counting sort), then W row block by row block: contact i meets
  // every contact j sharing one of its ranges, W_ij = Σ_b J_ib H_jb.
  std::vector<int> range_start(ranges.size() + 1, 0);
  for (const BlockRef& b : blocks) ++range_start[static_cast<std::size_t>(b.range) + 1];
  for (std::size_t r = 0; r < ranges.size(); ++r) range_start[r + 1] += range_start[r];
  std::vector<int> on_range(blocks.size());
  {
    std::vector<int> fill(range_start.begin(), range_start.end() - 1);
    for (std::size_t k = 0; k < blocks.size(); ++k)
      on_range[static_cast<std::size_t>(fill[static_cast<std::size_t>(blocks[k].range)]++)] =
          static_cast<int>(k);
  }
  struct Coupling {
    int contact;
    int own_block;    // index into blocks: contact i's block
    int other_block;  // index into blocks: contact j's block on the same range
  };
  std::vector<Coupling> couplings;
  std::vector<int> partners;
  std::vector<double> w_rows;  // dim × (dim · partners) of contact i, row-major
  W.resize(m * dim, m * dim);
  W.reserve(static_cast<Eigen::Index>(blocks.size()) * 4 * dim * dim);
  for (int i = 0; i < m; ++i) {
    couplings.clear();
    for (int k = contact_start[i]; k < contact_start[i + 1]; ++k) {
      const int r = blocks[static_cast<std::size_t>(k)].range;
      for (int p = range_start[static_cast<std::size_t>(r)];
           p < range_start[static_cast<std::size_t>(r) + 1]; ++p) {
        const int other = on_range[static_cast<std::size_t>(p)];
        couplings.push_back({blocks[static_cast<std::size_t>(other)].contact, k, other});
      }
    }
    std::sort(couplings.begin(), couplings.end(),
              [](const Coupling& a, const Coupling& b) { return a.contact < b.contact; });
    partners.clear();
    for (const Coupling& c : couplings)
      if (partners.empty() || partners.back() != c.contact) partners.push_back(c.contact);
    const std::size_t width = partners.size() * static_cast<std::size_t>(dim);
    w_rows.assign(static_cast<std::size_t>(dim) * width, 0.0);
    std::size_t slot = 0;  // the partner of the current coupling
    for (const Coupling& c : couplings) {
      while (partners[slot] != c.contact) ++slot;
      const BlockRef& own = blocks[static_cast<std::size_t>(c.own_block)];
      const BlockRef& other = blocks[static_cast<std::size_t>(c.other_block)];
      const int size = ranges[static_cast<std::size_t>(own.range)].size;
      const double* j_own = own.rows->data();  // dim × size, column-major
      const double* h_other = &h_storage[static_cast<std::size_t>(other.h_offset)];  // size × dim
      for (int rho = 0; rho < dim; ++rho)
        for (int col = 0; col < dim; ++col) {
          double sum = 0.0;
          for (int k = 0; k < size; ++k) sum += j_own[k * dim + rho] * h_other[col * size + k];
          w_rows[static_cast<std::size_t>(rho) * width + slot * static_cast<std::size_t>(dim) +
                 static_cast<std::size_t>(col)] += sum;
        }
    }
    for (int rho = 0; rho < dim; ++rho) {
      W.startVec(i * dim + rho);
      for (std::size_t p = 0; p < partners.size(); ++p)
        for (int col = 0; col < dim; ++col)
          W.insertBack(i * dim + rho, partners[p] * dim + col) =
              w_rows[static_cast<std::size_t>(rho) * width + p * static_cast<std::size_t>(dim) +
                     static_cast<std::size_t>(col)];
    }
  }
  W.finalize();
  return true;
}

}  // namespace impactbench::engines::moreau_jean
