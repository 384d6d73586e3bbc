// Lemke's pivoting decisions are relative: scaling a problem changes nothing but the scale of
// its answer. M and q scaled together by s leave z unchanged (w scales by s); q alone scaled by
// s scales z and w by s. Every answer is checked by a complementarity residual computed here,
// with w = Mz + q from Eigen's own product, on the problem's own scale.
#include <gtest/gtest.h>

#include <algorithm>

#include "solvers/friction/friction_solvers.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tests/support/solvers/independent_friction_residual.hpp"
#include "tests/support/solvers/lcp_test_problems.hpp"
#include "tests/support/solvers/random_friction_problem.hpp"

namespace impactbench::solvers {
namespace {

/// max_i |min(z_i / z_scale, w_i / w_scale)|, plus how negative z or w is on those scales: 0
/// exactly at a solution, independent of the problem's scale when the scales follow it.
double scaled_complementarity(const LcpProblem& problem, const Eigen::VectorXd& z, double z_scale,
                              double w_scale) {
  const Eigen::MatrixXd M = problem.is_sparse ? Eigen::MatrixXd(problem.sparse_M) : problem.dense_M;
  const Eigen::VectorXd w = M * z + problem.q;
  double worst = 0.0;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const double zi = z(i) / z_scale;
    const double wi = w(i) / w_scale;
    worst = std::max({worst, std::abs(std::min(zi, wi)), -zi, -wi});
  }
  return worst;
}

LcpProblem scaled(LcpProblem problem, double m_factor, double q_factor) {
  problem.dense_M *= m_factor;
  problem.sparse_M *= m_factor;
  problem.q *= q_factor;
  return problem;
}

SolverOptions loose_tolerance() {
  // The driver's residual ‖min(z, w)‖∞ is absolute: on a problem scaled by 1e-12 every z
  // satisfies any fixed tolerance or none. Pivoting does not use it; the checks here do not.
  SolverOptions options;
  options.tolerance = 1e300;
  options.max_iterations = 10000;
  return options;
}

TEST(LcpLemkeScaling, ProblemsScaledBy1eMinus12And1e12GiveTheSameSolution) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    for (const LcpProblem& base :
         {lcp::random_spd_problem(12, seed), lcp::random_nonsymmetric_pd_problem(12, seed),
          lcp::degenerate_psd_problem(12, seed)}) {
      const SolverResult reference = solve_lcp(base, "lemke", loose_tolerance());
      ASSERT_EQ(reference.status, SolverStatus::kConverged) << reference.message;
      ASSERT_LT(scaled_complementarity(base, reference.solution, 1.0, 1.0), 1e-12);
      for (const double s : {1e-12, 1e12}) {
        SCOPED_TRACE(testing::Message() << "seed " << seed << ", scale " << s);
        // M and q together: the same z, w scaled by s.
        const LcpProblem both = scaled(base, s, s);
        const SolverResult together = solve_lcp(both, "lemke", loose_tolerance());
        ASSERT_EQ(together.status, SolverStatus::kConverged) << together.message;
        EXPECT_LT(scaled_complementarity(both, together.solution, 1.0, s), 1e-12);
        // q alone: z and w scaled by s.
        const LcpProblem q_only = scaled(base, 1.0, s);
        const SolverResult alone = solve_lcp(q_only, "lemke", loose_tolerance());
        ASSERT_EQ(alone.status, SolverStatus::kConverged) << alone.message;
        EXPECT_LT(scaled_complementarity(q_only, alone.solution, s, s), 1e-12);
      }
    }
  }
}

// A planar friction problem with a tiny q (contacts barely approaching): its LCP form is exact,
// so Lemke must solve it to the FCLIB residual, which divides by ‖q‖ and is scale-free.
TEST(LcpLemkeScaling, PlanarFrictionProblemWithTinyQIsSolved) {
  for (const std::uint32_t seed : {5u, 6u, 7u}) {
    for (const double s : {1e-12, 1e12}) {
      SCOPED_TRACE(testing::Message() << "seed " << seed << ", q scaled by " << s);
      FrictionProblem problem = random_friction_problem({8, 16, 2, false, seed});
      problem.q *= s;
      SolverOptions options;
      options.tolerance = 1e-10;
      options.max_iterations = 100000;
      const SolverResult lemke = solve_friction(problem, "lemke", options);
      EXPECT_EQ(lemke.status, SolverStatus::kConverged) << lemke.message;
      EXPECT_LT(test_support::independent_friction_residual(problem, lemke.solution), 1e-10);
    }
  }
}

}  // namespace
}  // namespace impactbench::solvers
