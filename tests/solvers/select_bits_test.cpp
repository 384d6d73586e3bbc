// select_bits: c ? a : b, the chosen operand's bits exactly, for every kind of double (signed
// zeros, infinities, NaNs with payloads, subnormals), either way round.
#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "solvers/common/select_bits.hpp"
#include "tests/support/lib/double_bits.hpp"

namespace impactbench::solvers {
namespace {

TEST(SelectBits, ReturnsTheChosenOperandBitForBit) {
  const std::vector<double> values = {
      0.0,
      -0.0,
      1.0,
      -2.5,
      std::numeric_limits<double>::infinity(),
      -std::numeric_limits<double>::infinity(),
      std::numeric_limits<double>::denorm_min(),
      -std::numeric_limits<double>::max(),
      std::bit_cast<double>(std::uint64_t{0x7ff8000000000123}),  // a quiet NaN with a payload
      std::bit_cast<double>(std::uint64_t{0xfff0000000000001}),  // a negative signalling NaN
  };
  for (const double a : values) {
    for (const double b : values) {
      EXPECT_EQ(test_support::bits(select_bits(true, a, b)), test_support::bits(a));
      EXPECT_EQ(test_support::bits(select_bits(false, a, b)), test_support::bits(b));
    }
  }
}

}  // namespace
}  // namespace impactbench::solvers
