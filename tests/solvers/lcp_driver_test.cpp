// The LCP driver: registry, validation before solving, trivial case, status rules.
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "solvers/lcp/lcp_solvers.hpp"
#include "tests/support/solvers/lcp_test_problems.hpp"
#include "tests/support/solvers/same_result.hpp"

namespace impactbench::solvers {
namespace {

// w = M z + q with M = [[2, 1], [1, 2]], q = (−1, −1): z = (1/3, 1/3), w = 0 solves
// 2z_1 + z_2 = 1, z_1 + 2z_2 = 1 with both z_i > 0.
LcpProblem two_by_two() {
  Eigen::MatrixXd M(2, 2);
  M << 2, 1, 1, 2;
  return LcpProblem::dense(M, Eigen::Vector2d(-1, -1));
}

TEST(LcpDriver, RegistryListsEveryMethodOnce) {
  std::set<std::string> names;
  for (const SolverInfo& info : lcp_solvers()) {
    EXPECT_TRUE(names.insert(info.name).second) << info.name;
    EXPECT_FALSE(info.description.empty());
    EXPECT_GT(info.default_tolerance, 0.0);
    EXPECT_GT(info.default_max_iterations, 0);
  }
  EXPECT_EQ(names, (std::set<std::string>{"lemke", "pgs", "psor", "newton-fb", "enum"}));
}

TEST(LcpDriver, EverySolverSolvesTheTwoByTwoExample) {
  for (const SolverInfo& info : lcp_solvers()) {
    SCOPED_TRACE(info.name);
    SolverOptions options;
    options.tolerance = 1e-12;
    options.max_iterations = 10000;
    const SolverResult r = solve_lcp(two_by_two(), info.name, options);
    ASSERT_TRUE(r.converged()) << r.message;
    EXPECT_NEAR(r.solution(0), 1.0 / 3.0, 1e-11);
    EXPECT_NEAR(r.solution(1), 1.0 / 3.0, 1e-11);
    EXPECT_LT(r.velocity.cwiseAbs().maxCoeff(), 1e-11);
    EXPECT_GE(r.seconds, 0.0);
  }
}

// Turning the driver's timer off changes nothing but `seconds`, which says it was not measured.
TEST(LcpDriver, AnUntimedSolveHasTheSameAnswerAndNoTime) {
  for (const SolverInfo& info : lcp_solvers()) {
    SCOPED_TRACE(info.name);
    SolverOptions options;
    options.max_iterations = 10000;
    const SolverResult timed = solve_lcp(two_by_two(), info.name, options);
    options.measure_seconds = false;
    const SolverResult untimed = solve_lcp(two_by_two(), info.name, options);
    expect_untimed_like_timed(untimed, timed);
  }
}

TEST(LcpDriver, UnknownNameThrowsAndListsKnownNames) {
  try {
    solve_lcp(two_by_two(), "simplex");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'simplex'"), std::string::npos) << what;
    for (const SolverInfo& info : lcp_solvers()) {
      EXPECT_NE(what.find(info.name), std::string::npos) << what;
    }
  }
}

TEST(LcpDriver, NonFiniteDataIsRejectedBeforeSolving) {
  LcpProblem nan_q = two_by_two();
  nan_q.q(1) = std::numeric_limits<double>::quiet_NaN();
  LcpProblem inf_m = two_by_two();
  inf_m.dense_M(0, 1) = std::numeric_limits<double>::infinity();
  Eigen::SparseMatrix<double, Eigen::RowMajor> S = two_by_two().dense_M.sparseView();
  S.coeffRef(1, 0) = -std::numeric_limits<double>::infinity();
  const LcpProblem inf_sparse = LcpProblem::sparse(S, Eigen::Vector2d(-1, -1));
  const Eigen::VectorXd nan_warm = Eigen::Vector2d(0.0, std::numeric_limits<double>::quiet_NaN());
  for (const SolverInfo& info : lcp_solvers()) {
    SCOPED_TRACE(info.name);
    const SolverResult a = solve_lcp(nan_q, info.name);
    EXPECT_EQ(a.status, SolverStatus::kNonFiniteData);
    EXPECT_NE(a.message.find("q(1)"), std::string::npos) << a.message;
    EXPECT_EQ(a.iterations, 0);
    const SolverResult b = solve_lcp(inf_m, info.name);
    EXPECT_EQ(b.status, SolverStatus::kNonFiniteData);
    EXPECT_NE(b.message.find("M(0,1)"), std::string::npos) << b.message;
    const SolverResult c = solve_lcp(inf_sparse, info.name);
    EXPECT_EQ(c.status, SolverStatus::kNonFiniteData);
    EXPECT_NE(c.message.find("M(1,0)"), std::string::npos) << c.message;
    EXPECT_EQ(solve_lcp(two_by_two(), info.name, {}, &nan_warm).status,
              SolverStatus::kNonFiniteData);
  }
}

TEST(LcpDriver, InconsistentSizesAreInvalid) {
  const LcpProblem p = LcpProblem::dense(Eigen::MatrixXd::Identity(3, 2), -Eigen::Vector3d::Ones());
  const SolverResult r = solve_lcp(p, "pgs");
  EXPECT_EQ(r.status, SolverStatus::kInvalidProblem);
  EXPECT_NE(r.message.find("3x2"), std::string::npos) << r.message;
  const Eigen::VectorXd wrong_warm = Eigen::Vector3d::Zero();
  EXPECT_EQ(solve_lcp(two_by_two(), "pgs", {}, &wrong_warm).status, SolverStatus::kInvalidProblem);
  SolverOptions bad;
  bad.tolerance = -1.0;
  EXPECT_EQ(solve_lcp(two_by_two(), "lemke", bad).status, SolverStatus::kInvalidProblem);
}

// q ≥ 0: z = 0 solves the LCP (w = q ≥ 0, z ⊥ w), found without iterating.
TEST(LcpDriver, NonnegativeQIsSolvedByZero) {
  const LcpProblem p =
      LcpProblem::dense(-Eigen::MatrixXd::Identity(3, 3), Eigen::Vector3d(0, 1, 2));
  for (const SolverInfo& info : lcp_solvers()) {
    const SolverResult r = solve_lcp(p, info.name);
    ASSERT_TRUE(r.converged()) << info.name;
    EXPECT_EQ(r.solution, Eigen::Vector3d::Zero());
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(r.residual, 0.0);
  }
}

TEST(LcpDriver, EnumerationRefusesLargeProblems) {
  const SolverResult r = solve_lcp(lcp::random_spd_problem(15, 1), "enum");
  EXPECT_EQ(r.status, SolverStatus::kInvalidProblem);
  EXPECT_NE(r.message.find("15"), std::string::npos) << r.message;
  EXPECT_TRUE(solve_lcp(lcp::random_spd_problem(14, 1), "enum").converged());
}

TEST(LcpDriver, SweepsNeedPositiveDiagonalAndValidRelaxation) {
  LcpProblem p = two_by_two();
  p.dense_M(1, 1) = 0.0;
  const SolverResult r = solve_lcp(p, "pgs");
  EXPECT_EQ(r.status, SolverStatus::kSingular);
  EXPECT_NE(r.message.find("M(1,1)"), std::string::npos) << r.message;
  Eigen::SparseMatrix<double, Eigen::RowMajor> S = p.dense_M.sparseView();  // (1,1) not stored
  EXPECT_EQ(solve_lcp(LcpProblem::sparse(S, p.q), "psor").status, SolverStatus::kSingular);
  for (double omega : {0.0, 2.0, -0.5}) {
    SolverOptions options;
    options.relaxation = omega;
    EXPECT_EQ(solve_lcp(two_by_two(), "psor", options).status, SolverStatus::kInvalidProblem);
  }
}

TEST(LcpDriver, IterationLimitIsReported) {
  SolverOptions options;
  options.max_iterations = 2;
  options.tolerance = 1e-14;
  const LcpProblem p = lcp::random_spd_problem(50, 3);
  for (const char* name : {"pgs", "psor", "newton-fb", "lemke"}) {
    const SolverResult r = solve_lcp(p, name, options);
    EXPECT_EQ(r.status, SolverStatus::kMaxIterations) << name << ": " << r.message;
    EXPECT_EQ(r.iterations, 2) << name;
    EXPECT_GT(r.residual, options.tolerance) << name;
  }
}

// The driver trusts no claim of convergence: Lemke terminates on the n = 60 problem, but its
// rounding-level residual is above an absurdly small tolerance, so the status is not converged.
TEST(LcpDriver, ConvergenceClaimIsCheckedAgainstTheCommonResidual) {
  SolverOptions options;
  options.tolerance = 1e-300;
  options.max_iterations = 10000;
  const SolverResult r = solve_lcp(lcp::random_spd_problem(60, 5), "lemke", options);
  ASSERT_GT(r.residual, options.tolerance);  // the case this test is about
  EXPECT_LT(r.residual, 1e-12);              // the solution is still as good as rounding allows
  EXPECT_EQ(r.status, SolverStatus::kStalled);
  EXPECT_NE(r.message.find("above tolerance"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace impactbench::solvers
