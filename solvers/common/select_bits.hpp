#pragma once
// c ? a : b for doubles without a branch. A compiler turns a ?: on doubles back into a branch
// where it can, and where a condition follows the data (which case of a projection a contact
// falls in) the mispredicted branches cost more than forming both values. Both operands are
// formed by the caller; the answer is one of them, bit for bit.
#include <bit>
#include <cstdint>

namespace impactbench::solvers {

[[gnu::always_inline]] inline double select_bits(bool c, double a, double b) {
  const std::uint64_t mask = -static_cast<std::uint64_t>(c);  // all ones when c
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) |
                               (std::bit_cast<std::uint64_t>(b) & ~mask));
}

}  // namespace impactbench::solvers
