// nsgs and prox-gs keep their scratch per thread between solves (thread_kept.hpp). A solve
// started from a caller's monitor, on the same thread, while another solve holds that scratch
// must leave the outer solve's answer as it is: every answer here is compared bit for bit with
// the same problem solved with no solve inside it.
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "solvers/friction/friction_solvers.hpp"
#include "tests/support/solvers/random_friction_problem.hpp"

namespace impactbench::solvers {
namespace {

struct Case {
  std::string solver;
  bool factored;  // with factor blocks, the time stepper's form; else W formed sparse
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.solver << (c.factored ? " on factors" : " on W formed");
}

RandomFrictionSpec spec(int contacts, int dimension, bool factored, std::uint32_t seed) {
  RandomFrictionSpec s;
  s.contacts = contacts;
  s.bodies = 2 * contacts;
  s.dimension = dimension;
  s.sparse = !factored;
  s.factored = factored;
  s.factor_blocks = factored;
  s.seed = seed;
  return s;
}

void expect_same(const SolverResult& a, const SolverResult& b) {
  EXPECT_EQ(a.status, b.status) << a.message;
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.solution, b.solution);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.residual, b.residual);
}

class NestedFrictionSolve : public ::testing::TestWithParam<Case> {};

TEST_P(NestedFrictionSolve, LeavesTheOuterSolvesAnswerAsItIs) {
  const Case c = GetParam();
  for (const int dimension : {2, 3}) {
    SCOPED_TRACE(c.solver + " in dimension " + std::to_string(dimension));
    const FrictionProblem outer = random_friction_problem(spec(40, dimension, c.factored, 21));
    // Of another size and dimension, so that its scratch differs from the outer one's.
    const FrictionProblem inner = random_friction_problem(spec(7, 5 - dimension, c.factored, 22));
    SolverOptions options;
    options.tolerance = 1e-12;
    options.max_iterations = 200;
    const SolverResult expected_outer = solve_friction(outer, c.solver, options);
    const SolverResult expected_inner = solve_friction(inner, c.solver, options);
    ASSERT_GT(expected_outer.iterations, 2);  // a solve that calls its monitor

    int calls = 0;
    SolverOptions nesting = options;
    nesting.monitor = [&](int, double) {
      ++calls;
      expect_same(solve_friction(inner, c.solver, options), expected_inner);
      return true;
    };
    expect_same(solve_friction(outer, c.solver, nesting), expected_outer);
    EXPECT_GT(calls, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(SweepingSolvers, NestedFrictionSolve,
                         ::testing::Values(Case{"nsgs", true}, Case{"nsgs", false},
                                           Case{"prox-gs", true}, Case{"prox-gs", false},
                                           Case{"prox-jacobi", false}),
                         [](const ::testing::TestParamInfo<Case>& test) {
                           std::string name =
                               test.param.solver + (test.param.factored ? "_factored" : "_formed");
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace impactbench::solvers
