// The expression language of scenario files: the functions registered on top of muParser,
// errors for unknown names, dependency order and cycles of named expressions, and the
// thread safety of the shared compiled inputs.
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include "lib/scenario/expression.hpp"
#include "lib/scenario/named_expressions.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::scenario {
namespace {

double eval(const std::string& source) {
  VariableTable variables;
  variables.define("x", 2.0);
  return Expression(source, variables).evaluate();
}

TEST(Expression, RegisteredFunctions) {
  EXPECT_EQ(eval("floor(-2.5)"), -3.0);
  EXPECT_EQ(eval("ceil(2.1)"), 3.0);
  EXPECT_EQ(eval("mod(7, 3)"), 1.0);
  EXPECT_EQ(eval("mod(-1, 3)"), 2.0);  // sign of the divisor, as used for grid columns
  EXPECT_DOUBLE_EQ(eval("rad(180)"), M_PI);
  EXPECT_EQ(eval("x^2 - 1"), 3.0);
  EXPECT_EQ(eval("-x^2"), -4.0);  // power binds tighter than the sign
  EXPECT_EQ(eval("x > 1 ? 10 : 20"), 10.0);
}

TEST(Expression, TriangleIndexMatchesEnumeration) {
  int i = 0;
  for (int row = 0; row < 300; ++row)
    for (int column = 0; column <= row; ++column, ++i) {
      VariableTable variables;
      variables.define("i", i);
      ASSERT_EQ(Expression("tri_row(i)", variables).evaluate(), row) << i;
      ASSERT_EQ(Expression("tri_col(i)", variables).evaluate(), column) << i;
    }
}

TEST(Expression, RandIsDeterministicUniformAndIndexSensitive) {
  double sum = 0.0;
  const int n = 20000;
  int equal_neighbours = 0;
  for (int i = 0; i < n; ++i) {
    const double u = hashed_uniform(i, 0);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    equal_neighbours += u == hashed_uniform(i + 1, 0);
    ASSERT_EQ(u, hashed_uniform(i, 0));
    ASSERT_NE(u, hashed_uniform(i, 1));
  }
  EXPECT_EQ(equal_neighbours, 0);
  // Mean of n uniforms: standard deviation 1/sqrt(12 n) = 0.002; allow 5 of them.
  EXPECT_NEAR(sum / n, 0.5, 0.01);
  EXPECT_EQ(eval("rand(3, 4)"), hashed_uniform(3, 4));
  EXPECT_EQ(hashed_uniform(3.2, 4), hashed_uniform(3, 4));  // arguments are rounded
}

TEST(Expression, UnknownNamesAndSyntaxErrorsAreExplained) {
  VariableTable variables;
  variables.define("height", 1.0);
  try {
    Expression("heigth*2", variables);
    FAIL();
  } catch (const ExpressionError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("unknown name 'heigth'"), std::string::npos) << message;
    EXPECT_NE(message.find("known names: height"), std::string::npos) << message;
  }
  EXPECT_THROW(Expression("height*", variables), ExpressionError);
  EXPECT_THROW(Expression("sin(1, 2)", variables), ExpressionError);
  EXPECT_THROW(Expression("  ", variables), ExpressionError);
}

TEST(NamedExpressions, EvaluateDependenciesFirstAndFindCycles) {
  VariableTable variables;
  for (const auto* name : {"p", "a", "b", "c"}) variables.define(name, 0.0);
  variables.at("p") = 3.0;
  NamedExpressions named(variables);
  named.add("c", Expression("a + b", variables));  // defined before what it reads
  named.add("a", Expression("2*p", variables));
  named.add("b", Expression("a^2", variables));
  EXPECT_TRUE(named.find_cycle().empty());
  EXPECT_EQ(named.evaluate("c"), 6.0 + 36.0);
  variables.at("p") = 1.0;
  EXPECT_EQ(named.evaluate("c"), 2.0 + 4.0);  // re-evaluated, not cached
  EXPECT_TRUE(named.reads("c", "p"));
  EXPECT_FALSE(named.reads("a", "b"));

  NamedExpressions cyclic(variables);
  cyclic.add("a", Expression("b + 1", variables));
  cyclic.add("b", Expression("c", variables));
  cyclic.add("c", Expression("a", variables));
  EXPECT_EQ(cyclic.find_cycle(), (std::vector<std::string>{"a", "b", "c", "a"}));
}

TEST(ScenarioFunctions, InputIsTheForceExpressionOfTime) {
  const Scenario s = load_scenario_by_name("incline", {{"push_rate", 2.5}});
  ASSERT_EQ(s.input(0.0).size(), 1);
  EXPECT_EQ(s.input(0.0)[0], 0.0);
  EXPECT_EQ(s.input(1.5)[0], 3.75);
  EXPECT_EQ(load_scenario_by_name("bouncing_ball").input(1.0).size(), 0);
}

TEST(ScenarioFunctions, CopiesShareThreadSafeExpressions) {
  const Scenario s = load_scenario_by_name("incline");
  std::vector<std::thread> threads;
  std::vector<int> wrong(4, 0);
  for (int n = 0; n < 4; ++n)
    threads.emplace_back([copy = s, n, &wrong] {
      for (int i = 0; i < 2000; ++i) {
        const double t = n + i * 1e-3;
        wrong[static_cast<std::size_t>(n)] += copy.input(t)[0] != t;  // push_rate = 1
        wrong[static_cast<std::size_t>(n)] += copy.analytic("slip_time") <= 0.0;
      }
    });
  for (auto& thread : threads) thread.join();
  for (const int count : wrong) EXPECT_EQ(count, 0);
}

TEST(ScenarioFunctions, UnknownAnalyticNameListsTheValidOnes) {
  const Scenario s = load_scenario_by_name("sliding_block");
  try {
    s.analytic("stoptime");
    FAIL();
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("stop_time"), std::string::npos) << error.what();
  }
  EXPECT_THROW(s.parameter("speed"), std::invalid_argument);
}

}  // namespace
}  // namespace impactbench::scenario
