// one_component_norm: sqrt(x * x) to the bit, checked against the square root itself over the
// whole range of doubles, at the edges where x² stops being a normal number, and for the
// special values.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "solvers/common/one_component_norm.hpp"
#include "tests/support/lib/double_bits.hpp"

namespace impactbench::solvers {
namespace {

using test_support::bits;

// The same bits as sqrt(x²), or both NaN.
void expect_as_square_root(double x) {
  const double expected = std::sqrt(x * x);
  const double got = one_component_norm(x);
  if (std::isnan(expected)) {
    EXPECT_TRUE(std::isnan(got)) << x;
  } else {
    EXPECT_EQ(bits(got), bits(expected))
        << std::hexfloat << x << " gave " << got << ", not " << expected;
  }
}

TEST(OneComponentNorm, EqualsTheSquareRootOfTheSquareOverEveryExponent) {
  std::mt19937_64 random(20261129);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  long differs_from_magnitude = 0;  // where x² under- or overflows, sqrt(x²) is not |x|
  for (int exponent = -1074; exponent <= 1023; ++exponent) {
    for (int sample = 0; sample < 200; ++sample) {
      const double x = std::ldexp(mantissa(random), exponent) * (sample % 2 == 0 ? 1.0 : -1.0);
      if (!std::isfinite(x)) continue;
      expect_as_square_root(x);
      if (std::sqrt(x * x) != std::abs(x)) ++differs_from_magnitude;
    }
  }
  // The ranges the square root keeps are real: without them the answer would differ there.
  EXPECT_GT(differs_from_magnitude, 10000);
}

TEST(OneComponentNorm, EqualsTheSquareRootAtTheEdgesOfNormalSquares) {
  for (const double edge : {0x1p-511, 0x1p+511, 0x1p-537, 0x1p+512, 0x1p-1022}) {
    for (double x = edge, step = 0; step < 64; ++step) {
      expect_as_square_root(x);
      expect_as_square_root(-x);
      x = std::nextafter(x, 0.0);
    }
    for (double x = edge, step = 0; step < 64; ++step) {
      expect_as_square_root(x);
      x = std::nextafter(x, std::numeric_limits<double>::infinity());
    }
  }
}

TEST(OneComponentNorm, KeepsTheSpecialValues) {
  EXPECT_EQ(bits(one_component_norm(0.0)), bits(0.0));
  EXPECT_EQ(bits(one_component_norm(-0.0)), bits(0.0));
  EXPECT_EQ(one_component_norm(std::numeric_limits<double>::infinity()),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(one_component_norm(-std::numeric_limits<double>::infinity()),
            std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(one_component_norm(std::numeric_limits<double>::quiet_NaN())));
  expect_as_square_root(std::numeric_limits<double>::denorm_min());
  expect_as_square_root(std::numeric_limits<double>::max());
  expect_as_square_root(std::numeric_limits<double>::min());
}

}  // namespace
}  // namespace impactbench::solvers
