// Lemke solves problems of 2 to 12 unknowns on a tableau whose size is fixed at compile time and
// forms the answer's w = M z + q itself (lemke.cpp). Its w must be the driver's own formula's to
// the bit at every size, on both sides of that range, for dense and sparse M, and the answer
// must be a solution.
#include <gtest/gtest.h>

#include "solvers/lcp/lcp_residual.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tests/support/solvers/lcp_test_problems.hpp"

namespace impactbench::solvers {
namespace {

void expect_velocity_of_the_driver(const LcpProblem& problem) {
  SolverOptions options;
  options.max_iterations = 10000;
  const SolverResult result = solve_lcp(problem, "lemke", options);
  ASSERT_TRUE(result.converged()) << result.message;
  EXPECT_LE(result.residual, options.tolerance);
  const Eigen::VectorXd w = lcp::lcp_velocity(problem, result.solution);
  ASSERT_EQ(result.velocity.size(), w.size());
  EXPECT_TRUE((result.velocity.array() == w.array()).all()) << (result.velocity - w).transpose();
  EXPECT_EQ(result.residual, lcp::natural_map_residual(result.solution, w));
}

TEST(LcpLemkeFixedSize, TheAnswersVelocityIsTheDriversFormulaAtEverySize) {
  for (int n = 1; n <= 15; ++n) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed " + std::to_string(seed));
      expect_velocity_of_the_driver(lcp::random_spd_problem(n, seed));
      expect_velocity_of_the_driver(lcp::random_nonsymmetric_pd_problem(n, seed));
    }
  }
}

TEST(LcpLemkeFixedSize, ASparseMatrixGivesTheDriversFormulaToo) {
  for (const int n : {3, 8, 12, 20}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    expect_velocity_of_the_driver(lcp::random_sparse_contact_problem(n, 7));
  }
}

}  // namespace
}  // namespace impactbench::solvers
