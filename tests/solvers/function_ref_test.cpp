// FunctionRef calls the callable it refers to (not a copy of it), with the arguments given, and
// returns its result; an empty one says so.
#include <gtest/gtest.h>

#include "solvers/common/function_ref.hpp"

namespace impactbench::solvers {
namespace {

TEST(FunctionRef, CallsTheReferencedCallableWithItsArgumentsAndState) {
  int calls = 0;
  double last = 0.0;
  const auto scale = [&](double x, int k) {
    ++calls;
    last = x;
    return x * k;
  };
  const FunctionRef<double(double, int)> ref = scale;
  ASSERT_TRUE(static_cast<bool>(ref));
  EXPECT_EQ(ref(1.5, 4), 6.0);
  EXPECT_EQ(ref(-2.0, 3), -6.0);
  EXPECT_EQ(calls, 2);  // the captured state is the lambda's own, not a copy's
  EXPECT_EQ(last, -2.0);
}

TEST(FunctionRef, WritesThroughReferenceArguments) {
  const auto add_one = [](int& value) { ++value; };
  const FunctionRef<void(int&)> ref = add_one;
  int value = 41;
  ref(value);
  EXPECT_EQ(value, 42);
}

TEST(FunctionRef, DefaultConstructedIsEmpty) {
  const FunctionRef<void()> empty;
  EXPECT_FALSE(static_cast<bool>(empty));
}

}  // namespace
}  // namespace impactbench::solvers
