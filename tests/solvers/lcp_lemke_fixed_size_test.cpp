// Lemke solves problems of 2 to 12 unknowns on a tableau whose size is fixed at compile time and
// forms the answer's w = M z + q itself (lemke.cpp). Its w must be the driver's own formula's to
// the bit at every size, on both sides of that range, for dense and sparse M, and the answer
// must be a solution. Its pivots must be those of the tableau of a size known at run time, to the
// bit, whether its loops take the rows one by one or in pairs.
#include <gtest/gtest.h>

#include <algorithm>

#include "solvers/lcp/lcp_methods.hpp"
#include "solvers/lcp/lcp_residual.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tests/support/solvers/lcp_test_problems.hpp"
#include "tests/support/solvers/same_result.hpp"

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

/// Compares the two tableaux on `problem`; returns the pivots made.
int expect_the_run_time_sizes_pivots(const LcpProblem& problem) {
  SolverOptions options;
  options.max_iterations = 10000;
  lcp::LcpMethodResult fixed;
  const Eigen::VectorXd no_start;  // Lemke starts from w = q
  lcp::solve_lemke(problem, options, no_start, fixed);
  lcp::LcpMethodResult run_time;
  lcp::solve_lemke_at_run_time_size(problem, options, run_time);
  EXPECT_EQ(fixed.status, run_time.status) << fixed.message;
  EXPECT_EQ(fixed.iterations, run_time.iterations);
  EXPECT_TRUE(same_bits(fixed.z, run_time.z)) << fixed.z.transpose() << "\n"
                                              << run_time.z.transpose();
  EXPECT_TRUE(same_bits(fixed.w, run_time.w));
  EXPECT_EQ(fixed.residual, run_time.residual);
  return fixed.iterations;
}

TEST(LcpLemkeFixedSize, PivotsAsTheRunTimeSizeTableauToTheBit) {
  for (int n = 2; n <= 12; ++n) {
    int most_pivots = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed " + std::to_string(seed));
      for (const LcpProblem& problem :
           {lcp::random_spd_problem(n, seed), lcp::random_nonsymmetric_pd_problem(n, seed),
            // Ties in the ratio test: the lexicographic rule's loops over B⁻¹'s columns.
            lcp::degenerate_psd_problem(n, seed)}) {
        most_pivots = std::max(most_pivots, expect_the_run_time_sizes_pivots(problem));
      }
    }
    SCOPED_TRACE("Murty's problem reversed, n = " + std::to_string(n));
    most_pivots =
        std::max(most_pivots, expect_the_run_time_sizes_pivots(lcp::reversed_murty_problem(n)));
    // Reversed, Murty's problem takes 2^n pivots: every size pivots beyond z0's first.
    EXPECT_GE(most_pivots, n);
  }
}

}  // namespace
}  // namespace impactbench::solvers
