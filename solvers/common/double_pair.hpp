#pragma once
// Two doubles operated on as one (a 16-byte vector of the compiler's vector extensions), for the
// short loops of a small tableau whose length is fixed at compile time: there the compiler
// unrolled the loops into scalar code rather than vectorising them. Each operation acts on each
// lane as the scalar operation does on its value (IEEE addition, multiplication, comparison,
// selection; no fused multiply-add), so a loop over pairs gives the bits of the scalar loop.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace impactbench::solvers {

using DoublePair = double __attribute__((vector_size(16)));
/// The bits of a DoublePair, for masks.
using BitsPair = std::uint64_t __attribute__((vector_size(16)));

/// The two doubles at `values` (no alignment needed).
inline DoublePair load_pair(const double* values) {
  DoublePair pair;
  std::memcpy(&pair, values, sizeof pair);
  return pair;
}

inline void store_pair(double* values, DoublePair pair) {
  std::memcpy(values, &pair, sizeof pair);
}

/// |x| per lane as std::abs forms it: the sign bit cleared (of −0 and of a NaN too).
inline DoublePair abs_pair(DoublePair x) {
  constexpr std::uint64_t kMagnitude = ~(std::uint64_t{1} << 63);
  return std::bit_cast<DoublePair>(std::bit_cast<BitsPair>(x) & kMagnitude);
}

/// x with lane `lane` (0 or 1) set to +0.
inline DoublePair with_lane_zeroed(DoublePair x, int lane) {
  const BitsPair keep = lane == 0 ? BitsPair{0, ~std::uint64_t{0}} : BitsPair{~std::uint64_t{0}, 0};
  return std::bit_cast<DoublePair>(std::bit_cast<BitsPair>(x) & keep);
}

/// std::max(a, b) per lane: b where a < b, else a (so a NaN in b gives a, and a NaN in a stays).
inline DoublePair max_pair(DoublePair a, DoublePair b) {
  return a < b ? b : a;
}

// The same operations on one value (double) or a pair (DoublePair), for loops whose body serves
// both: the pairs first, then what is left one by one.
template <typename Rows>
Rows load_rows(const double* values) {
  if constexpr (std::is_same_v<Rows, DoublePair>) {
    return load_pair(values);
  } else {
    return *values;
  }
}
inline void store_rows(double* values, double value) {
  *values = value;
}
inline void store_rows(double* values, DoublePair pair) {
  store_pair(values, pair);
}
inline double magnitude(double x) {
  return std::abs(x);
}
inline DoublePair magnitude(DoublePair x) {
  return abs_pair(x);
}
inline double larger(double a, double b) {
  return std::max(a, b);
}
inline DoublePair larger(DoublePair a, DoublePair b) {
  return max_pair(a, b);
}

/// The first n values set to `value`, the first `kPaired` (even) of them written in pairs.
template <int kPaired>
void fill_rows(double* values, int n, double value) {
  int i = 0;
  for (; i < kPaired; i += 2) store_pair(values + i, DoublePair{value, value});
  for (; i < n; ++i) values[i] = value;
}

/// The first n values copied from `source`, the first `kPaired` (even) of them in pairs.
template <int kPaired>
void copy_rows(const double* source, int n, double* values) {
  int i = 0;
  for (; i < kPaired; i += 2) store_pair(values + i, load_pair(source + i));
  for (; i < n; ++i) values[i] = source[i];
}

}  // namespace impactbench::solvers
