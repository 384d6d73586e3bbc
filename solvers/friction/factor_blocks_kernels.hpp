#pragma once
// The loops over a factored problem's FactorBlocks, shared by the Gauss–Seidel sweep and the
// products of delassus_access: a contact's rows of H times w, and a change of one of its
// impulse components carried into w along its columns of A. Each sum runs in the order of the
// sparse factors' own products (ranges, then columns or rows, ascending), so the results are
// those of factor_H and factor_A to the bit: the blocks' extra zeros of H add +0 to sums of
// finite terms.
#include <type_traits>

#include "solvers/friction/friction_problem.hpp"

namespace impactbench::solvers::factor_blocks {

/// Calls f with the size of a block's range as a compile-time constant where it is a rigid
/// body's (3 planar, 6 spatial velocities), so that the loops over it unroll, else as an int.
template <typename F>
[[gnu::always_inline]] inline void with_block_size(int size, F&& f) {
  if (size == 3)
    f(std::integral_constant<int, 3>{});
  else if (size == 6)
    f(std::integral_constant<int, 6>{});
  else
    f(size);
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
    with_block_size(blocks.size[k], [&](auto size) {
      for (int col = 0; col < size; ++col)
        for (int row = 0; row < D; ++row) out[row] += h[col * D + row] * w_range[col];
    });
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
    with_block_size(blocks.size[k], [&](auto size) {
      const double* a = block + size * D;
      for (int component = 0; component < D; ++component)
        for (int row = 0; row < size; ++row)
          w_range[row] += a[component * size + row] * change[component];
    });
  }
}

/// out (D × D, row-major) += W_ii = Σ_b J_ib H_ib, each entry summed over the ranges in order.
template <int D>
void add_contact_diagonal_block(const FactorBlocks& blocks, int contact, double* out) {
  const auto i = static_cast<std::size_t>(contact);
  for (int b = blocks.contact_start[i]; b < blocks.contact_start[i + 1]; ++b) {
    const auto k = static_cast<std::size_t>(b);
    const double* h = &blocks.values[static_cast<std::size_t>(blocks.offset[k])];
    with_block_size(blocks.size[k], [&](auto size) {
      const double* a = h + size * D;
      for (int row = 0; row < D; ++row)
        for (int col = 0; col < D; ++col)
          for (int s = 0; s < size; ++s) out[row * D + col] += h[s * D + row] * a[col * size + s];
    });
  }
}

/// Calls f with the problem's dimension (2 or 3) as a compile-time constant.
template <typename F>
decltype(auto) with_dimension(int dimension, F&& f) {
  if (dimension == 2) return f(std::integral_constant<int, 2>{});
  return f(std::integral_constant<int, 3>{});
}

}  // namespace impactbench::solvers::factor_blocks
