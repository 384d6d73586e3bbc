// Errors binned in time over tosses: each toss counts once per bin with the mean of its samples
// there, and bins no toss reaches are left out.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "lib/validation/error_over_time.hpp"

namespace impactbench::validation {
namespace {

TEST(ErrorOverTime, EachTossCountsOncePerBinWithTheMeanOfItsSamples) {
  // Toss A: samples at 0, 0.05, 0.1 s (two in bin 0, one in bin 1 of width 0.1 s).
  // Toss B: samples at 0, 0.25 s (bin 0, bin 2); nobody else reaches bin 2.
  const std::vector<std::vector<SampleError>> tosses = {
      {{0.0, 1.0, 0.1}, {0.05, 3.0, 0.3}, {0.1, 5.0, 0.5}},
      {{0.0, 4.0, 0.4}, {0.25, 6.0, 0.6}},
  };
  const auto bins = error_over_time(tosses, 0.1);
  ASSERT_EQ(bins.size(), 3u);
  // Bin 0: A's mean (1 + 3)/2 = 2 and B's 4: mean 3, median 3, p90 2 + 0.9·2 = 3.8.
  EXPECT_DOUBLE_EQ(bins[0].start, 0.0);
  EXPECT_EQ(bins[0].position.count, 2);
  EXPECT_DOUBLE_EQ(bins[0].position.mean, 3.0);
  EXPECT_DOUBLE_EQ(bins[0].position.p90, 3.8);
  EXPECT_DOUBLE_EQ(bins[0].rotation.mean, 0.3);
  // Bin 1: A alone; bin 2: B alone.
  EXPECT_DOUBLE_EQ(bins[1].start, 0.1);
  EXPECT_EQ(bins[1].position.count, 1);
  EXPECT_DOUBLE_EQ(bins[1].position.median, 5.0);
  EXPECT_DOUBLE_EQ(bins[2].start, 0.2);
  EXPECT_DOUBLE_EQ(bins[2].rotation.mean, 0.6);
}

TEST(ErrorOverTime, ABinWidthThatIsNotPositiveAndFiniteIsRefused) {
  const std::vector<std::vector<SampleError>> tosses = {{{0.0, 1.0, 0.1}}};
  for (const double width : {0.0, -0.1, std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()})
    EXPECT_THROW(error_over_time(tosses, width), std::invalid_argument) << width;
  EXPECT_TRUE(error_over_time({}, 0.1).empty());
}

}  // namespace
}  // namespace impactbench::validation
