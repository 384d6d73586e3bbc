// FrictionSolver::solve into a kept SolverResult (the time stepper's way, which reuses the
// result's storage from step to step) gives what a solve into a new result gives, to the bit,
// whatever the kept result held before: answers of other sizes, representations and solvers, a
// failure, or a solve that ended at its entry check.
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "solvers/friction/friction_solvers.hpp"
#include "tests/support/solvers/random_friction_problem.hpp"
#include "tests/support/solvers/same_result.hpp"

namespace impactbench::solvers {
namespace {

struct Case {
  std::string solver;
  RandomFrictionSpec spec;
  int max_iterations;
};

TEST(FrictionKeptResult, EqualsANewResultWhateverItHeldBefore) {
  // Sizes that shrink and grow, every representation, solvers that stop converged, at their
  // iteration limit (a message-free status) and through the LCP form (a faceted residual).
  const std::vector<Case> cases = {
      {"nsgs", {40, 80, 3, false, 1, true, true}, 1000},
      {"nsgs", {7, 14, 3, false, 2, true, true}, 1000},
      {"nsgs", {60, 120, 2, false, 3, true, false}, 3},
      {"lemke", {12, 24, 3, false, 4}, 1000},
      {"nsn", {25, 50, 3, true, 5}, 1000},
      {"prox-gs", {9, 18, 2, false, 6}, 1000},
      {"nsgs", {40, 80, 3, false, 7, true, true}, 1000},
  };
  SolverResult kept;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.solver + " on " + std::to_string(c.spec.contacts) + " contacts");
    const FrictionProblem problem = random_friction_problem(c.spec);
    SolverOptions options;
    options.tolerance = 1e-10;
    options.max_iterations = c.max_iterations;
    const FrictionSolver solver(c.solver);
    const SolverResult fresh = solver.solve(problem, options);
    solver.solve(problem, options, nullptr, kept);
    expect_same_result(kept, fresh);

    // Warm-started from its own answer: a solve that may end at the entry check.
    const Eigen::VectorXd start = fresh.solution;
    const SolverResult fresh_warm = solver.solve(problem, options, &start);
    solver.solve(problem, options, &start, kept);
    expect_same_result(kept, fresh_warm);
  }
}

TEST(FrictionKeptResult, RejectedProblemLeavesNothingOfTheKeptAnswer) {
  const FrictionSolver solver("nsgs");
  SolverResult kept;
  solver.solve(random_friction_problem({10, 20, 3, false, 1}), {}, nullptr, kept);
  ASSERT_TRUE(kept.converged()) << kept.message;

  FrictionProblem bad = random_friction_problem({10, 20, 3, false, 1});
  bad.q(3) = std::numeric_limits<double>::quiet_NaN();
  const SolverResult fresh = solver.solve(bad);
  solver.solve(bad, {}, nullptr, kept);
  EXPECT_EQ(kept.status, SolverStatus::kNonFiniteData);
  EXPECT_EQ(kept.solution.size(), 0);
  EXPECT_EQ(kept.velocity.size(), 0);
  expect_same_result(kept, fresh);
}

}  // namespace
}  // namespace impactbench::solvers
