// solve_lcp into a kept SolverResult (for callers that solve many problems in a row; Lemke reuses
// the result's storage) gives what a solve into a new result gives, to the bit, whatever the kept
// result held before: answers of other sizes and methods, a secondary ray, an iteration limit, a
// trivial q ≥ 0, or a problem rejected at the entry check.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "solvers/lcp/lcp_solvers.hpp"
#include "tests/support/solvers/lcp_test_problems.hpp"
#include "tests/support/solvers/same_result.hpp"

namespace impactbench::solvers {
namespace {

using lcp::murty_problem;
using lcp::random_sparse_contact_problem;
using lcp::random_spd_problem;

// M = [[1, −1], [−1, 1]], q = (−1, −1): w ≥ 0 needs z_1 − z_2 ≥ 1 and z_2 − z_1 ≥ 1, which no z
// meets, so Lemke ends on a secondary ray.
LcpProblem infeasible_problem() {
  Eigen::MatrixXd M(2, 2);
  M << 1, -1, -1, 1;
  return LcpProblem::dense(M, Eigen::Vector2d(-1, -1));
}

struct Case {
  std::string label;
  std::string solver;
  LcpProblem problem;
  int max_iterations;
  SolverStatus expected;
};

TEST(LcpKeptResult, EqualsANewResultWhateverItHeldBefore) {
  // Sizes that grow and shrink; Lemke solved, on a ray, at its pivot limit and on q ≥ 0; the
  // other methods, whose answers replace the kept storage.
  const std::vector<Case> cases = {
      {"lemke spd 30", "lemke", random_spd_problem(30, 1), 1000, SolverStatus::kConverged},
      {"lemke spd 3", "lemke", random_spd_problem(3, 2), 1000, SolverStatus::kConverged},
      {"lemke ray", "lemke", infeasible_problem(), 1000, SolverStatus::kRayTermination},
      {"lemke murty 6", "lemke", murty_problem(6), 1000, SolverStatus::kConverged},
      {"lemke limit", "lemke", random_spd_problem(30, 1), 3, SolverStatus::kMaxIterations},
      {"lemke q >= 0", "lemke",
       LcpProblem::dense(Eigen::MatrixXd::Identity(4, 4), Eigen::Vector4d(0, 1, 2, 3)), 1000,
       SolverStatus::kConverged},
      {"pgs spd 12", "pgs", random_spd_problem(12, 3), 10000, SolverStatus::kConverged},
      {"lemke sparse 40", "lemke", random_sparse_contact_problem(40, 4), 1000,
       SolverStatus::kConverged},
      {"enum spd 5", "enum", random_spd_problem(5, 5), 1 << 10, SolverStatus::kConverged},
      {"newton-fb spd 8", "newton-fb", random_spd_problem(8, 6), 100, SolverStatus::kConverged},
      {"lemke spd 30 again", "lemke", random_spd_problem(30, 1), 1000, SolverStatus::kConverged},
  };
  SolverResult kept;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.label);
    SolverOptions options;
    options.max_iterations = c.max_iterations;
    const SolverResult fresh = solve_lcp(c.problem, c.solver, options);
    EXPECT_EQ(fresh.status, c.expected) << fresh.message;
    solve_lcp(c.problem, c.solver, options, nullptr, kept);
    expect_same_result(kept, fresh);
    EXPECT_TRUE(std::isnan(kept.faceted_residual));
  }
}

TEST(LcpKeptResult, RejectedProblemLeavesNothingOfTheKeptAnswer) {
  SolverResult kept;
  solve_lcp(random_spd_problem(10, 1), "lemke", {}, nullptr, kept);
  ASSERT_TRUE(kept.converged()) << kept.message;

  LcpProblem bad = random_spd_problem(10, 1);
  bad.q(3) = std::numeric_limits<double>::quiet_NaN();
  const SolverResult fresh = solve_lcp(bad, "lemke");
  solve_lcp(bad, "lemke", {}, nullptr, kept);
  EXPECT_EQ(kept.status, SolverStatus::kNonFiniteData);
  expect_same_result(kept, fresh);
  EXPECT_EQ(kept.solution, Eigen::VectorXd::Zero(10));
  EXPECT_EQ(kept.velocity.size(), 0);
  EXPECT_TRUE(std::isnan(kept.residual));
  EXPECT_EQ(kept.seconds, 0.0);
}

}  // namespace
}  // namespace impactbench::solvers
