#pragma once
// A double's bits, for tests that expect a value to the bit: +0 and −0 differ, and a NaN
// compares by its payload. EXPECT_EQ on them prints both values in full.
#include <bit>
#include <cstdint>

namespace impactbench::test_support {

inline std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

}  // namespace impactbench::test_support
