// A time stepper solves one friction problem a step into the same result, and the number of
// active contacts comes and goes. Once the result and the solver's kept scratch have met the
// largest problem, a solve of that size or smaller allocates nothing: the answer, the contact
// velocity, the warm start and the scratch all keep their storage. Counted by the counting
// allocator (tests/support/heap), every malloc of the process included.
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "solvers/common/capacity_vector.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "tests/support/heap/heap_allocations.hpp"
#include "tests/support/solvers/random_friction_problem.hpp"

namespace impactbench::solvers {
namespace {

struct SolverCase {
  std::string solver;
  int dimension;
};

void PrintTo(const SolverCase& c, std::ostream* out) {
  *out << c.solver << (c.dimension == 2 ? " planar" : " spatial");
}

class KeptSolveAllocations : public ::testing::TestWithParam<SolverCase> {};

TEST_P(KeptSolveAllocations, NoneOnceTheLargestProblemHasBeenSolved) {
  const SolverCase& c = GetParam();
  // Factored by contact blocks, as the stepper assembles them: the largest first, then sizes
  // that shrink and grow below it.
  std::vector<FrictionProblem> problems;
  for (const int contacts : {40, 25, 40, 12, 33, 1})
    problems.push_back(random_friction_problem(
        {contacts, 2 * contacts, c.dimension, false, static_cast<unsigned>(contacts), true, true}));
  // Warm starts as the stepper gathers them: half of each problem's answer, in kept storage.
  std::vector<CapacityVector> warm_starts;
  const FrictionSolver solver(c.solver);
  SolverOptions options;
  options.tolerance = 1e-9;
  options.max_iterations = 5000;
  options.measure_seconds = false;
  for (const FrictionProblem& problem : problems) {
    const SolverResult answer = solver.solve(problem, options);
    ASSERT_TRUE(answer.converged()) << c.solver << ": " << answer.message;
    warm_starts.emplace_back(0.5 * answer.solution);
  }

  SolverResult kept;
  solver.solve(problems.front(), options, nullptr, kept);  // meets the largest size
  for (int round = 0; round < 2; ++round) {
    for (std::size_t k = 0; k < problems.size(); ++k) {
      SCOPED_TRACE("problem " + std::to_string(k) + ", round " + std::to_string(round));
      const WarmStart warm_start = round == 0 ? WarmStart() : WarmStart(&warm_starts[k]);
      const long before = heap::allocations();
      solver.solve(problems[k], options, warm_start, kept);
      const long allocated = heap::allocations() - before;
      ASSERT_TRUE(kept.converged()) << kept.message;
      EXPECT_EQ(allocated, 0);
      EXPECT_EQ(kept.solution.size(), problems[k].size());
      EXPECT_EQ(kept.velocity.size(), problems[k].size());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(SweepingSolvers, KeptSolveAllocations,
                         ::testing::Values(SolverCase{"nsgs", 2}, SolverCase{"nsgs", 3},
                                           SolverCase{"prox-gs", 2}, SolverCase{"prox-gs", 3}),
                         [](const auto& param_info) {
                           return (param_info.param.solver == "nsgs" ? std::string("nsgs")
                                                                     : std::string("prox_gs")) +
                                  (param_info.param.dimension == 2 ? "_planar" : "_spatial");
                         });

// The proximal-point solvers on a W given formed (sparse), as the time stepper gives it to
// prox-jacobi: the residual after every sweep keeps its u and divisor, so a solve into a kept
// result allocates nothing once it has met the largest problem, whatever its sweep count.
TEST(FormedProblemSolveAllocations, NoneOnceTheLargestProblemHasBeenSolved) {
  for (const char* name : {"prox-jacobi", "prox-gs"}) {
    for (const int dimension : {2, 3}) {
      SCOPED_TRACE(std::string(name) + (dimension == 2 ? " planar" : " spatial"));
      std::vector<FrictionProblem> problems;
      for (const int contacts : {30, 12, 30})
        problems.push_back(random_friction_problem(
            {contacts, 2 * contacts, dimension, true, static_cast<unsigned>(contacts)}));
      const FrictionSolver solver(name);
      SolverOptions options;
      options.tolerance = 1e-9;
      options.max_iterations = 5000;
      options.measure_seconds = false;
      SolverResult kept;
      solver.solve(problems.front(), options, nullptr, kept);  // meets the largest size
      ASSERT_TRUE(kept.converged()) << kept.message;
      for (std::size_t k = 0; k < problems.size(); ++k) {
        const long before = heap::allocations();
        solver.solve(problems[k], options, nullptr, kept);
        const long allocated = heap::allocations() - before;
        ASSERT_TRUE(kept.converged()) << "problem " << k << ": " << kept.message;
        EXPECT_GT(kept.iterations, 10) << "problem " << k;  // many residuals evaluated
        EXPECT_EQ(allocated, 0) << "problem " << k;
      }
    }
  }
}

}  // namespace
}  // namespace impactbench::solvers
