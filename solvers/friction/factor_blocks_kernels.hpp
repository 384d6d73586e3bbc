#pragma once
// The loops over a factored problem's FactorBlocks, shared by the Gauss–Seidel sweep and the
// products of delassus_access: a contact's rows of H times w, and a change of one of its
// impulse components carried into w along its columns of A. Each sum runs in the order of the
// sparse factors' own products (ranges, then columns or rows, ascending), so the results are
// those of factor_H and factor_A to the bit: the blocks' extra zeros of H add +0 to sums of
// finite terms. Two independent sums at a time go through a pair of SIMD lanes (Eigen's
// Array2d), whose products and sums are each lane's own scalar ones, rounded alike.
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "solvers/friction/friction_problem.hpp"

namespace impactbench::solvers::factor_blocks {

/// Calls f with `value` as a compile-time constant (std::integral_constant) when it is one of
/// `Constants`, else as an int: loops bounded by it then unroll for the common values.
template <int... Constants, typename F>
[[gnu::always_inline]] inline void with_constant(int value, F&& f) {
  const bool matched =
      ((value == Constants ? (f(std::integral_constant<int, Constants>{}), true) : false) || ...);
  if (!matched) f(value);
}

/// Calls f with the size of a block's range as a compile-time constant where it is a rigid
/// body's (3 planar, 6 spatial velocities), so that the loops over it unroll, else as an int.
template <typename F>
[[gnu::always_inline]] inline void with_block_size(int size, F&& f) {
  with_constant<3, 6>(size, std::forward<F>(f));
}

/// out[row] += (H_b w_b)_row for one block: its H entries `h` (D × size, column-major) and
/// the velocities of its range. `size` an int or a compile-time constant.
template <int D, typename Size>
[[gnu::always_inline]] inline void add_block_rows(const double* h, const double* w_range, Size size,
                                                  double* out) {
  // Rows 0 and 1 in one pair of lanes: each lane's products and sums are the scalar ones.
  Eigen::Map<Eigen::Array2d> first_rows(out);
  Eigen::Array2d pair = first_rows;
  for (int col = 0; col < size; ++col)
    pair += Eigen::Map<const Eigen::Array2d>(h + col * D) * w_range[col];
  first_rows = pair;
  for (int col = 0; col < size; ++col)
    for (int row = 2; row < D; ++row) out[row] += h[col * D + row] * w_range[col];
}

/// w_b += A_b · change for one block: its values `block` (H, then A as size × D, column-major)
/// and the velocities of its range.
template <int D, typename Size>
[[gnu::always_inline]] inline void add_block_columns(const double* block, const double* change,
                                                     Size size, double* w_range) {
  const double* a = block + size * D;
  // Rows in pairs of lanes, each row still summed over the components in order.
  int row = 0;
  for (; row + 1 < size; row += 2) {
    Eigen::Map<Eigen::Array2d> rows(w_range + row);
    Eigen::Array2d pair = rows;
    for (int component = 0; component < D; ++component)
      pair += Eigen::Map<const Eigen::Array2d>(a + component * size + row) * change[component];
    rows = pair;
  }
  for (; row < size; ++row)
    for (int component = 0; component < D; ++component)
      w_range[row] += a[component * size + row] * change[component];
}

/// out[row] += (H_i w)_row for the D rows of contact i.
template <int D>
[[gnu::always_inline]] inline void add_contact_rows(const FactorBlocks& blocks, int contact,
                                                    const double* w, double* out) {
  const auto i = static_cast<std::size_t>(contact);
  for (int b = blocks.contact_start[i]; b < blocks.contact_start[i + 1]; ++b) {
    const auto k = static_cast<std::size_t>(b);
    const double* h = &blocks.values[static_cast<std::size_t>(blocks.offset[k])];
    const double* w_range = w + blocks.first_velocity[k];
    with_block_size(blocks.size[k], [&](auto size) { add_block_rows<D>(h, w_range, size, out); });
  }
}

/// w += A_i · change: the velocity that follows a change of contact i's D impulse components
/// (a zero change adds +0, which leaves w as it is).
template <int D>
[[gnu::always_inline]] inline void add_contact_columns(const FactorBlocks& blocks, int contact,
                                                       const double* change, double* w) {
  const auto i = static_cast<std::size_t>(contact);
  for (int b = blocks.contact_start[i]; b < blocks.contact_start[i + 1]; ++b) {
    const auto k = static_cast<std::size_t>(b);
    const double* block = &blocks.values[static_cast<std::size_t>(blocks.offset[k])];
    double* w_range = w + blocks.first_velocity[k];
    with_block_size(blocks.size[k],
                    [&](auto size) { add_block_columns<D>(block, change, size, w_range); });
  }
}

/// out (D × D, row-major) += H_b A_b for one block: its values `block` (H, then A) over a range
/// of `size` velocities (an int or a compile-time constant), each entry summed over the range in
/// order.
template <int D, typename Size>
[[gnu::always_inline]] inline void add_block_diagonal(const double* block, Size size, double* out) {
  const double* h = block;
  const double* a = block + size * D;
  // Rows 0 and 1 of each column in one pair of lanes, each entry summed over s in order.
  for (int col = 0; col < D; ++col) {
    Eigen::Array2d pair(out[col], out[D + col]);
    for (int s = 0; s < size; ++s)
      pair += Eigen::Map<const Eigen::Array2d>(h + s * D) * a[col * size + s];
    out[col] = pair(0);
    out[D + col] = pair(1);
  }
  for (int row = 2; row < D; ++row)
    for (int col = 0; col < D; ++col)
      for (int s = 0; s < size; ++s) out[row * D + col] += h[s * D + row] * a[col * size + s];
}

/// out (D × D, row-major) += W_ii = Σ_b J_ib H_ib, each entry summed over the ranges in order.
template <int D>
void add_contact_diagonal_block(const FactorBlocks& blocks, int contact, double* out) {
  const auto i = static_cast<std::size_t>(contact);
  for (int b = blocks.contact_start[i]; b < blocks.contact_start[i + 1]; ++b) {
    const auto k = static_cast<std::size_t>(b);
    const double* block = &blocks.values[static_cast<std::size_t>(blocks.offset[k])];
    with_block_size(blocks.size[k], [&](auto size) { add_block_diagonal<D>(block, size, out); });
  }
}

/// A contact's blocks as the sweeps and products read them when every block is a rigid body's
/// (kRigidSize<D> velocities: 3 planar, 6 spatial) and there are at most two: the block
/// pointers and ranges at hand, without the index arrays and the dispatch on the block size.
/// count = -1: blocks of another kind, read through the general kernels above.
struct RigidContactBlocks {
  const double* values[2];
  int first_velocity[2];
  int count;
};
template <int D>
inline constexpr int kRigidSize = D == 2 ? 3 : 6;

/// One description per contact of `blocks` (a solve makes them once and reads them every sweep).
template <int D>
void describe_rigid_contacts(const FactorBlocks& blocks, std::vector<RigidContactBlocks>& out) {
  const auto contacts = static_cast<std::size_t>(blocks.contacts());
  out.resize(contacts);
  for (std::size_t i = 0; i < contacts; ++i) {
    RigidContactBlocks& c = out[i];
    const int first = blocks.contact_start[i];
    const int count = blocks.contact_start[i + 1] - first;
    c.count = count <= 2 ? count : -1;
    for (int n = 0; n < count && c.count >= 0; ++n) {
      const auto k = static_cast<std::size_t>(first + n);
      if (blocks.size[k] != kRigidSize<D>) {
        c.count = -1;
        break;
      }
      c.values[n] = &blocks.values[static_cast<std::size_t>(blocks.offset[k])];
      c.first_velocity[n] = blocks.first_velocity[k];
    }
  }
}

/// Contact i's description, or null when there are none or its blocks are of another kind.
[[gnu::always_inline]] inline const RigidContactBlocks* described(
    const std::vector<RigidContactBlocks>* rigid, int contact) {
  if (rigid == nullptr) return nullptr;
  const RigidContactBlocks& c = (*rigid)[static_cast<std::size_t>(contact)];
  return c.count >= 0 ? &c : nullptr;
}

/// add_contact_rows for contact i, through its description when it has one (`rigid` may be
/// null): the same sums in the same order.
template <int D>
[[gnu::always_inline]] inline void add_rows(const FactorBlocks& blocks,
                                            const std::vector<RigidContactBlocks>* rigid,
                                            int contact, const double* w, double* out) {
  const RigidContactBlocks* c = described(rigid, contact);
  if (c == nullptr) return add_contact_rows<D>(blocks, contact, w, out);
  for (int n = 0; n < c->count; ++n)
    add_block_rows<D>(c->values[n], w + c->first_velocity[n],
                      std::integral_constant<int, kRigidSize<D>>{}, out);
}

/// add_contact_columns for contact i, through its description when it has one.
template <int D>
[[gnu::always_inline]] inline void add_columns(const FactorBlocks& blocks,
                                               const std::vector<RigidContactBlocks>* rigid,
                                               int contact, const double* change, double* w) {
  const RigidContactBlocks* c = described(rigid, contact);
  if (c == nullptr) return add_contact_columns<D>(blocks, contact, change, w);
  for (int n = 0; n < c->count; ++n)
    add_block_columns<D>(c->values[n], change, std::integral_constant<int, kRigidSize<D>>{},
                         w + c->first_velocity[n]);
}

/// add_contact_diagonal_block for contact i, through its description when it has one: the same
/// sums in the same order.
template <int D>
[[gnu::always_inline]] inline void add_diagonal(const FactorBlocks& blocks,
                                                const std::vector<RigidContactBlocks>* rigid,
                                                int contact, double* out) {
  const RigidContactBlocks* c = described(rigid, contact);
  if (c == nullptr) return add_contact_diagonal_block<D>(blocks, contact, out);
  for (int n = 0; n < c->count; ++n)
    add_block_diagonal<D>(c->values[n], std::integral_constant<int, kRigidSize<D>>{}, out);
}

/// For each contact in order, its W_ii (D × D, row-major, add_diagonal's sums into zeros) given
/// to `use(i, w_ii)`, for the solvers that prepare their steps from it; false at the first
/// contact whose W_nn is not positive (or NaN), before `use` sees it.
template <int D, typename Use>
bool for_each_positive_diagonal(const FactorBlocks& blocks,
                                const std::vector<RigidContactBlocks>* rigid, Use&& use) {
  const int contacts = blocks.contacts();
  for (int i = 0; i < contacts; ++i) {
    double w_ii[D * D] = {};
    add_diagonal<D>(blocks, rigid, i, w_ii);
    if (!(w_ii[0] > 0.0)) return false;
    use(i, std::as_const(w_ii));
  }
  return true;
}

/// One Gauss–Seidel pass over the contacts of a factored problem by blocks, w = A r kept along:
/// for each contact i, (W r)_i = H_i w into `row_times`, then `update(i, row_times, r_i, r_new)`
/// writes the new impulse into r_new (which holds r_i on the call), and w follows the change
/// along A's columns before r_i takes it (shared by nsgs and prox-gs).
template <int D, typename Update>
[[gnu::always_inline]] inline void gauss_seidel_pass(const FactorBlocks& blocks,
                                                     const std::vector<RigidContactBlocks>& rigid,
                                                     int contacts, double* r, double* w,
                                                     Update&& update) {
  for (int i = 0; i < contacts; ++i) {
    double row_times[D] = {};
    add_rows<D>(blocks, &rigid, i, w, row_times);
    double* r_i = r + static_cast<std::ptrdiff_t>(i) * D;
    double r_new[D];
    for (int k = 0; k < D; ++k) r_new[k] = r_i[k];
    update(i, static_cast<const double*>(row_times), static_cast<const double*>(r_i), r_new);
    double change[D];
    bool moved = false;
    for (int k = 0; k < D; ++k) {
      change[k] = r_new[k] - r_i[k];
      moved = moved || r_new[k] != r_i[k];
      r_i[k] = r_new[k];
    }
    if (moved) add_columns<D>(blocks, &rigid, i, change, w);
  }
}

/// True when all D components of x are zero (either sign).
template <int D>
[[gnu::always_inline]] inline bool is_zero(const double* x) {
  bool zero = true;
  for (int k = 0; k < D; ++k) zero = zero && x[k] == 0.0;
  return zero;
}

/// Calls f with the problem's dimension (2 or 3) as a compile-time constant.
template <typename F>
decltype(auto) with_dimension(int dimension, F&& f) {
  if (dimension == 2) return f(std::integral_constant<int, 2>{});
  return f(std::integral_constant<int, 3>{});
}

}  // namespace impactbench::solvers::factor_blocks
