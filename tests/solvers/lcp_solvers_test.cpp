// Accuracy of every LCP solver against the enumeration oracle and against independent checks of
// 0 ≤ z ⊥ M z + q ≥ 0 (computed here with a dense product, not with the driver's residual).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "solvers/lcp/lcp_solvers.hpp"
#include "tests/support/solvers/lcp_test_problems.hpp"

namespace impactbench::solvers {
namespace {

using lcp::degenerate_psd_problem;
using lcp::murty_problem;
using lcp::random_diagonally_dominant_problem;
using lcp::random_nonsymmetric_pd_problem;
using lcp::random_spd_problem;

Eigen::MatrixXd dense_matrix(const LcpProblem& p) {
  return p.is_sparse ? Eigen::MatrixXd(p.sparse_M) : p.dense_M;
}

// Largest violation of z ≥ 0, w ≥ 0 and z_i w_i = 0, each scaled by the size of the data.
double complementarity_violation(const LcpProblem& p, const Eigen::VectorXd& z) {
  const Eigen::VectorXd w = dense_matrix(p) * z + p.q;
  const double scale = 1.0 + p.q.cwiseAbs().maxCoeff() + z.cwiseAbs().maxCoeff();
  double worst = 0.0;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    worst = std::max({worst, -z(i), -w(i), std::abs(z(i) * w(i)) / scale});
  }
  return worst / scale;
}

SolverOptions tight(double tolerance, int max_iterations) {
  SolverOptions options;
  options.tolerance = tolerance;
  options.max_iterations = max_iterations;
  return options;
}

SolverResult oracle(const LcpProblem& p) {
  const SolverResult result = solve_lcp(p, "enum");
  EXPECT_TRUE(result.converged()) << result.message;
  EXPECT_LT(complementarity_violation(p, result.solution), 1e-12);
  return result;
}

void expect_matches_oracle(const LcpProblem& p, const std::vector<std::string>& solvers,
                           const SolverOptions& options) {
  const Eigen::VectorXd expected = oracle(p).solution;
  for (const std::string& name : solvers) {
    SCOPED_TRACE(name);
    const SolverResult result = solve_lcp(p, name, options);
    ASSERT_TRUE(result.converged()) << to_string(result.status) << ": " << result.message;
    EXPECT_LT((result.solution - expected).cwiseAbs().maxCoeff(), 1e-8);
  }
}

// P-matrix LCPs have exactly one solution, so every solver must find the oracle's.
TEST(LcpSolvers, SymmetricPositiveDefiniteAgreeWithEnumeration) {
  for (int n = 1; n <= 10; ++n) {
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
      SolverOptions options = tight(1e-13, 100000);
      options.relaxation = 1.3;
      expect_matches_oracle(random_spd_problem(n, seed), {"lemke", "newton-fb", "pgs", "psor"},
                            options);
    }
  }
}

TEST(LcpSolvers, NonsymmetricPMatricesAgreeWithEnumeration) {
  for (int n = 1; n <= 10; ++n) {
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
      const SolverOptions options = tight(1e-12, 1000);
      expect_matches_oracle(random_nonsymmetric_pd_problem(n, seed), {"lemke", "newton-fb"},
                            options);
      expect_matches_oracle(random_diagonally_dominant_problem(n, 100 + seed),
                            {"lemke", "newton-fb"}, options);
    }
  }
}

// Murty's problem: a triangular P-matrix whose unique solution is z = e_n (w = (1,…,1,0)).
TEST(LcpSolvers, MurtyProblemSolvedByLemke) {
  const int n = 10;
  const LcpProblem p = murty_problem(n);
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(n);
  expected(n - 1) = 1.0;
  Eigen::VectorXd expected_w = Eigen::VectorXd::Ones(n);
  expected_w(n - 1) = 0.0;
  const SolverResult lemke = solve_lcp(p, "lemke", tight(1e-12, 1 << 12));
  ASSERT_TRUE(lemke.converged()) << lemke.message;
  EXPECT_LT((lemke.solution - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((lemke.velocity - expected_w).cwiseAbs().maxCoeff(), 1e-12);
  expect_matches_oracle(p, {"lemke", "newton-fb"}, tight(1e-12, 1 << 12));
}

// The same problem with the indices reversed (solution z = e_1) is the ordering on which
// Lemke's path visits every one of the 2^n vertices (Murty 1978): with the lexicographic
// tie-break (which favours the last row among the tied q_i = −1) that is what ours does.
TEST(LcpSolvers, ReversedMurtyProblemTakesExponentiallyManyPivots) {
  for (int n : {2, 5, 10}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    const LcpProblem p = lcp::reversed_murty_problem(n);
    const SolverResult lemke = solve_lcp(p, "lemke", tight(1e-12, 1 << 12));
    ASSERT_TRUE(lemke.converged()) << lemke.message;
    EXPECT_EQ(lemke.iterations, 1 << n);
    EXPECT_LT((lemke.solution - Eigen::VectorXd::Unit(n, 0)).cwiseAbs().maxCoeff(), 1e-12);
    // With too few pivots allowed Lemke must say so, not claim a solution.
    const SolverResult cut = solve_lcp(p, "lemke", tight(1e-12, (1 << n) - 1));
    EXPECT_EQ(cut.status, SolverStatus::kMaxIterations);
  }
}

// Larger SPD problems: the driver's residual and an independent check.
TEST(LcpSolvers, RandomSpdUpTo200) {
  for (int n : {20, 50, 200}) {
    for (std::uint64_t seed = 0; seed < 2; ++seed) {
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
      const LcpProblem p = random_spd_problem(n, 1000 + seed);
      for (const char* name : {"lemke", "newton-fb"}) {
        SCOPED_TRACE(name);
        const SolverResult r = solve_lcp(p, name, tight(1e-10, 10000));
        ASSERT_TRUE(r.converged()) << r.message;
        EXPECT_LT(r.residual, 1e-10);
        EXPECT_LT(complementarity_violation(p, r.solution), 1e-10);
      }
      const SolverResult pgs = solve_lcp(p, "pgs", tight(1e-6, 10000));
      ASSERT_TRUE(pgs.converged()) << pgs.message;
      EXPECT_LT(pgs.residual, 1e-6);
      EXPECT_LT(complementarity_violation(p, pgs.solution), 1e-6);
    }
  }
}

// Rank-deficient PSD M with duplicated rows and a degenerate solution: the lexicographic rule
// must keep Lemke from cycling (a cycle would end at the pivot limit, not in a solution).
TEST(LcpSolvers, LemkeTerminatesOnDegenerateProblems) {
  for (int n : {3, 4, 6, 9, 12, 20, 40}) {
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
      const LcpProblem p = degenerate_psd_problem(n, seed);
      const SolverResult r = solve_lcp(p, "lemke", tight(1e-9, 100 * n));
      ASSERT_TRUE(r.converged()) << to_string(r.status) << ": " << r.message;
      EXPECT_LT(complementarity_violation(p, r.solution), 1e-9);
      if (n <= 12) {  // the oracle confirms a solution exists and agrees on the residual scale
        EXPECT_LT(complementarity_violation(p, oracle(p).solution), 1e-9);
      }
    }
  }
}

// The same problems for the Newton method: H is (nearly) singular at such solutions, which the
// Levenberg–Marquardt fallback must handle within a small number of steps.
TEST(LcpSolvers, NewtonFbSolvesDegenerateProblems) {
  for (int n : {6, 12, 40, 100}) {
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
      const LcpProblem p = degenerate_psd_problem(n, seed);
      const SolverResult r = solve_lcp(p, "newton-fb", tight(1e-9, 100));
      ASSERT_TRUE(r.converged()) << to_string(r.status) << ": " << r.message;
      EXPECT_LT(complementarity_violation(p, r.solution), 1e-9);
    }
  }
}

// M = 1 1ᵀ, q = −1: every ratio in every step ties; the solutions are z ≥ 0 with Σ z = 1.
TEST(LcpSolvers, LemkeOnAllTiedRank1Problem) {
  const int n = 8;
  const LcpProblem p = LcpProblem::dense(Eigen::MatrixXd::Ones(n, n), -Eigen::VectorXd::Ones(n));
  const SolverResult r = solve_lcp(p, "lemke");
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.solution.sum(), 1.0, 1e-14);
  EXPECT_GE(r.solution.minCoeff(), 0.0);
  EXPECT_LT(complementarity_violation(p, r.solution), 1e-14);
}

// M = −I, q = −1 has no solution (w = −z − 1 < 0 whenever z ≥ 0): no solver may converge.
TEST(LcpSolvers, InfeasibleProblemNeverConverges) {
  const int n = 4;
  const LcpProblem p =
      LcpProblem::dense(-Eigen::MatrixXd::Identity(n, n), -Eigen::VectorXd::Ones(n));
  for (const SolverInfo& info : lcp_solvers()) {
    SCOPED_TRACE(info.name);
    const SolverResult r = solve_lcp(p, info.name, tight(1e-10, 200));
    EXPECT_FALSE(r.converged());
    // |min(z_i, −z_i − 1)| ≥ 1/2 for every real z_i (equality at z_i = −1/2).
    EXPECT_GE(r.residual, 0.5 - 1e-12);
  }
  EXPECT_EQ(solve_lcp(p, "lemke").status, SolverStatus::kRayTermination);
}

// M = [[−1, 0], [0, 1]], q = (q₀, 1), q₀ < 0. Lemke's first pivot brings in z0 at level −q₀ in
// row 0 (w₀ leaves); z₀ enters next, with column B⁻¹ (1, 0) = (−1, −1) for B = [−d, e₁]: no
// positive entry, a secondary ray, with z = 0 and w = q, so ‖min(z, w)‖∞ = |q₀|.
LcpProblem ray_after_one_pivot(double q0) {
  Eigen::MatrixXd M(2, 2);
  M << -1.0, 0.0, 0.0, 1.0;
  return LcpProblem::dense(M, Eigen::Vector2d(q0, 1.0));
}

// A ray reached where z already meets the tolerance (z0 of rounding size) is an answer like any
// solver's: converged, the ray named in the message. Above the tolerance it is a failure.
TEST(LcpLemke, SecondaryRayWithZWithinToleranceIsConverged) {
  const SolverResult within = solve_lcp(ray_after_one_pivot(-1e-14), "lemke", tight(1e-10, 200));
  EXPECT_TRUE(within.converged()) << within.message;
  EXPECT_EQ(within.solution, Eigen::Vector2d::Zero());
  EXPECT_EQ(within.residual, 1e-14);
  EXPECT_EQ(within.iterations, 1);
  EXPECT_NE(within.message.find("secondary ray after 1 pivots with z already a solution"),
            std::string::npos)
      << within.message;
  const SolverResult beyond = solve_lcp(ray_after_one_pivot(-1e-3), "lemke", tight(1e-10, 200));
  EXPECT_EQ(beyond.status, SolverStatus::kRayTermination);
  EXPECT_EQ(beyond.residual, 1e-3);
  EXPECT_NE(beyond.message.find("secondary ray after 1 pivots"), std::string::npos)
      << beyond.message;
}

// Warm start: from the exact solution the iterative methods stop at once.
TEST(LcpSolvers, WarmStartFromSolutionStopsImmediately) {
  const LcpProblem p = random_spd_problem(30, 7);
  const SolverResult reference = solve_lcp(p, "lemke");
  ASSERT_TRUE(reference.converged());
  const SolverResult pgs = solve_lcp(p, "pgs", tight(1e-8, 100), &reference.solution);
  ASSERT_TRUE(pgs.converged()) << pgs.message;
  EXPECT_EQ(pgs.iterations, 1);
  const SolverResult newton = solve_lcp(p, "newton-fb", tight(1e-8, 100), &reference.solution);
  ASSERT_TRUE(newton.converged()) << newton.message;
  EXPECT_EQ(newton.iterations, 0);
  // And a warm start near the solution needs fewer sweeps than a cold one.
  const Eigen::VectorXd nearby = reference.solution.array() + 1e-3;
  const SolverResult cold = solve_lcp(p, "pgs", tight(1e-10, 10000));
  const SolverResult warm = solve_lcp(p, "pgs", tight(1e-10, 10000), &nearby);
  ASSERT_TRUE(cold.converged() && warm.converged());
  EXPECT_LT(warm.iterations, cold.iterations);
}

// PGS and PSOR on sparse contact-like problems (never densified) agree with Lemke.
TEST(LcpSolvers, SparseProblemsAgreeWithLemke) {
  for (std::uint64_t seed = 0; seed < 3; ++seed) {
    const LcpProblem p = lcp::random_sparse_contact_problem(60, seed, 0.1);
    const SolverResult lemke = solve_lcp(p, "lemke");
    ASSERT_TRUE(lemke.converged()) << lemke.message;
    SolverOptions options = tight(1e-11, 200000);
    for (double omega : {1.0, 0.7, 1.4}) {
      options.relaxation = omega;
      for (const char* name : {"psor", "newton-fb"}) {
        SCOPED_TRACE(std::string(name) + " omega " + std::to_string(omega));
        const SolverResult r = solve_lcp(p, name, options);
        ASSERT_TRUE(r.converged()) << r.message;
        EXPECT_LT((r.solution - lemke.solution).cwiseAbs().maxCoeff(), 1e-7);
      }
    }
  }
}

}  // namespace
}  // namespace impactbench::solvers
