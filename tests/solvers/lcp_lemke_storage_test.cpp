// Lemke keeps its tableau's storage per thread for small problems (lemke.cpp, StorageLease).
// What a solve returns must not depend on what that storage held before, nor on a solve
// running inside another one on the same thread (from a caller's monitor): every answer here
// is compared bit for bit with the same problem solved on a fresh thread, whose storage is new.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "solvers/lcp/lcp_solvers.hpp"
#include "tests/support/solvers/lcp_test_problems.hpp"

namespace impactbench::solvers {
namespace {

SolverOptions lemke_options() {
  SolverOptions options;
  options.tolerance = 1e-10;
  options.max_iterations = 10000;
  return options;
}

SolverResult solve_on_fresh_thread(const LcpProblem& problem) {
  SolverResult result;
  std::thread([&] { result = solve_lcp(problem, "lemke", lemke_options()); }).join();
  return result;
}

void expect_same_answer(const SolverResult& a, const SolverResult& b) {
  ASSERT_TRUE(a.converged()) << a.message;
  ASSERT_TRUE(b.converged()) << b.message;
  EXPECT_EQ(a.iterations, b.iterations);
  ASSERT_EQ(a.solution.size(), b.solution.size());
  EXPECT_TRUE((a.solution.array() == b.solution.array()).all());
  EXPECT_TRUE((a.velocity.array() == b.velocity.array()).all());
}

// Sizes below, at and above the kept size (64), in an order that leaves larger problems'
// values in the storage before smaller ones and then larger ones again.
TEST(LemkeStorage, AnswersDoNotDependOnEarlierSolves) {
  const std::vector<LcpProblem> problems = {
      lcp::random_spd_problem(40, 11),
      lcp::random_spd_problem(3, 12),
      lcp::murty_problem(6),
      lcp::random_spd_problem(64, 13),
      lcp::random_spd_problem(9, 14),
      lcp::random_spd_problem(80, 15),
      lcp::degenerate_psd_problem(20, 16),
      lcp::random_spd_problem(2, 17),
  };
  for (std::size_t k = 0; k < problems.size(); ++k) {
    SCOPED_TRACE(k);
    expect_same_answer(solve_lcp(problems[k], "lemke", lemke_options()),
                       solve_on_fresh_thread(problems[k]));
  }
}

// A monitor that solves another problem at every pivot of the outer solve: the inner solves
// must not take the storage the outer tableau is using.
TEST(LemkeStorage, SolveInsideAMonitorLeavesTheOuterSolveIntact) {
  const LcpProblem outer = lcp::random_spd_problem(30, 21);
  const LcpProblem inner = lcp::random_spd_problem(12, 22);
  const SolverResult inner_alone = solve_on_fresh_thread(inner);
  int inner_solves = 0;
  SolverOptions options = lemke_options();
  options.monitor = [&](int, double) {
    expect_same_answer(solve_lcp(inner, "lemke", lemke_options()), inner_alone);
    ++inner_solves;
    return true;
  };
  const SolverResult nested = solve_lcp(outer, "lemke", options);
  const SolverResult outer_alone = solve_on_fresh_thread(outer);
  expect_same_answer(nested, outer_alone);
  // The monitor runs after every pivot but the first and the one that ends the solve.
  EXPECT_EQ(inner_solves, outer_alone.iterations - 2);
  EXPECT_GT(inner_solves, 0);
}

}  // namespace
}  // namespace impactbench::solvers
