// all_finite: true exactly when no value is NaN or infinite, at any size and position; a sum of
// finite values that overflows (the check starts from the sum) is still finite data.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "solvers/common/all_finite.hpp"

namespace impactbench::solvers {
namespace {

bool each_finite(const Eigen::MatrixXd& values) {
  for (Eigen::Index k = 0; k < values.size(); ++k) {
    if (!std::isfinite(values.data()[k])) return false;
  }
  return true;
}

TEST(AllFinite, AgreesWithAValueByValueCheckAtEverySizeAndPosition) {
  const double bad_values[] = {std::numeric_limits<double>::quiet_NaN(),
                               std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity()};
  for (const Eigen::Index rows : {0, 1, 2, 3, 4, 5, 7, 16, 17, 40}) {
    for (const Eigen::Index cols : {1, 2, 3}) {
      SCOPED_TRACE(std::to_string(rows) + "x" + std::to_string(cols));
      Eigen::MatrixXd values = Eigen::MatrixXd::Constant(rows, cols, 0.5);
      EXPECT_TRUE(all_finite(values));
      EXPECT_TRUE(all_finite(values.data(), values.size()));
      for (Eigen::Index k = 0; k < values.size(); ++k) {
        for (const double bad : bad_values) {
          Eigen::MatrixXd with_bad = values;
          with_bad.data()[k] = bad;
          ASSERT_FALSE(each_finite(with_bad));
          EXPECT_FALSE(all_finite(with_bad)) << "value " << k << " = " << bad;
          EXPECT_FALSE(all_finite(with_bad.data(), with_bad.size())) << k;
          EXPECT_FALSE(all_finite(with_bad.col(k / rows))) << k;
        }
      }
    }
  }
}

TEST(AllFinite, FiniteValuesWhoseSumOverflowsAreFinite) {
  for (const Eigen::Index n : {2, 16, 17, 64}) {
    const Eigen::VectorXd huge = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::max());
    ASSERT_FALSE(std::isfinite(huge.sum()));
    EXPECT_TRUE(all_finite(huge)) << n;
  }
}

}  // namespace
}  // namespace impactbench::solvers
