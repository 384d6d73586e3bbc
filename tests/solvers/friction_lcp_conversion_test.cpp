// Friction contact → LCP (lcp_conversion.hpp): the matrix by hand, the exactness of the planar
// form checked against nsgs without any LCP solver, then Lemke on the LCP against nsgs.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "solvers/friction/lcp_conversion.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tests/support/solvers/random_friction_problem.hpp"

namespace impactbench::solvers {
namespace {

double natural_residual(const LcpProblem& lcp, const Eigen::VectorXd& z) {
  const Eigen::VectorXd w =
      (lcp.is_sparse ? Eigen::MatrixXd(lcp.sparse_M) : lcp.dense_M) * z + lcp.q;
  return z.cwiseMin(w).lpNorm<Eigen::Infinity>();
}

SolverOptions tight() {
  SolverOptions options;
  options.tolerance = 1e-12;
  options.max_iterations = 20000;
  return options;
}

// One planar contact, W = [[a, b], [b, c]], z = (r_n, α₊, α₋, β), r_t = α₊ − α₋:
//   w_n = a r_n + b (α₊ − α₋) + q_n,       w₊ = b r_n + c (α₊ − α₋) + q_t + β,
//   w₋ = −(b r_n + c (α₊ − α₋) + q_t) + β,  w_β = μ r_n − α₊ − α₋.
TEST(FrictionLcpConversion, PlanarMatrixByHand) {
  const double a = 2.0, b = 0.5, c = 1.5, mu = 0.4;
  Eigen::Matrix2d w;
  w << a, b, b, c;
  const FrictionProblem problem =
      FrictionProblem::dense(2, w, Eigen::Vector2d(-1.0, 0.7), Eigen::VectorXd::Constant(1, mu));
  const FrictionLcp conversion = friction_to_lcp(problem, 8);
  Eigen::Matrix4d expected;
  expected << a, b, -b, 0.0,  //
      b, c, -c, 1.0,          //
      -b, -c, c, 1.0,         //
      mu, -1.0, -1.0, 0.0;
  ASSERT_FALSE(conversion.lcp.is_sparse);
  EXPECT_LT((conversion.lcp.dense_M - expected).norm(), 1e-15);
  EXPECT_LT((conversion.lcp.q - Eigen::Vector4d(-1.0, 0.7, -0.7, 0.0)).norm(), 1e-15);
  EXPECT_EQ(impulse_from_lcp(conversion, Eigen::VectorXd(Eigen::Vector4d(1.0, 0.2, 0.5, 3.0))),
            Eigen::Vector2d(1.0, -0.3));
}

// Spatial: k unit directions at angles 2πj/k, all in T's tangential rows.
TEST(FrictionLcpConversion, SpatialFacetDirections) {
  const FrictionProblem problem = random_friction_problem({2, 4, 3, true, 3});
  const FrictionLcp conversion = friction_to_lcp(problem, 6);
  ASSERT_EQ(conversion.directions, 6);
  ASSERT_EQ(conversion.lcp.size(), 2 * 8);
  ASSERT_TRUE(conversion.lcp.is_sparse);
  const Eigen::MatrixXd t = conversion.to_impulse;
  for (int j = 0; j < 6; ++j) {
    const double angle = 2.0 * std::numbers::pi * j / 6;
    EXPECT_NEAR(t(1, 1 + j), std::cos(angle), 1e-15);
    EXPECT_NEAR(t(2, 1 + j), std::sin(angle), 1e-15);
  }
  EXPECT_THROW(friction_to_lcp(problem, 2), std::invalid_argument);
}

// The planar LCP is exact: the nsgs solution, written as z (r_t split into α₊, α₋, β = |u_t|),
// solves the LCP. Checked for dense and sparse W, without any LCP solver.
TEST(FrictionLcpConversion, PlanarSolutionOfFrictionSolvesTheLcp) {
  for (const bool sparse : {false, true}) {
    const FrictionProblem problem = random_friction_problem({25, 50, 2, sparse, 9});
    const SolverResult friction = solve_friction(problem, "nsgs", tight());
    ASSERT_TRUE(friction.converged()) << friction.message;
    const FrictionLcp conversion = friction_to_lcp(problem, 8);
    const Eigen::VectorXd z = lcp_point_from_impulse(problem, conversion, friction.solution);
    EXPECT_LT(natural_residual(conversion.lcp, z), 1e-9);
    EXPECT_LT((impulse_from_lcp(conversion, z) - friction.solution).norm(), 1e-12);
  }
}

// Lemke on the planar LCP gives the nsgs solution (unique here: W positive definite).
TEST(FrictionLcpConversion, PlanarLemkeMatchesNonsmoothGaussSeidel) {
  const FrictionProblem problem = random_friction_problem({20, 40, 2, false, 13});
  const SolverResult nsgs = solve_friction(problem, "nsgs", tight());
  const SolverResult lemke = solve_friction(problem, "lemke", tight());
  ASSERT_TRUE(nsgs.converged()) << nsgs.message;
  ASSERT_TRUE(lemke.converged()) << lemke.message;
  EXPECT_LT((lemke.solution - nsgs.solution).lpNorm<Eigen::Infinity>(), 1e-8);
}

// Block PGS on the same LCPs: in the plane it converges to nsgs's solution (dense and sparse W);
// in space to the faceted cone's solution, the one Lemke finds.
TEST(FrictionLcpConversion, BlockPgsMatchesNsgsInThePlaneAndLemkeInSpace) {
  for (const bool sparse : {false, true}) {
    SCOPED_TRACE(sparse ? "sparse" : "dense");
    const FrictionProblem planar = random_friction_problem({20, 40, 2, sparse, 13});
    const SolverResult nsgs = solve_friction(planar, "nsgs", tight());
    const SolverResult pgs = solve_friction(planar, "pgs", tight());
    ASSERT_TRUE(nsgs.converged()) << nsgs.message;
    ASSERT_TRUE(pgs.converged()) << pgs.message;
    EXPECT_LT((pgs.solution - nsgs.solution).lpNorm<Eigen::Infinity>(), 1e-8);

    const FrictionProblem spatial = random_friction_problem({10, 20, 3, sparse, 21});
    const SolverResult lemke = solve_friction(spatial, "lemke", tight());
    const SolverResult faceted_pgs = solve_friction(spatial, "pgs", tight());
    // Both stop on the LCP; the disk residual of the faceted answer stays above 1e-12: the
    // status says the faceted problem was solved, and both residuals are reported.
    for (const SolverResult* faceted : {&lemke, &faceted_pgs}) {
      EXPECT_EQ(faceted->status, SolverStatus::kConvergedFaceted) << faceted->message;
      EXPECT_LE(faceted->faceted_residual, tight().tolerance);
      EXPECT_GT(faceted->residual, tight().tolerance);
      EXPECT_NE(faceted->message.find("faceted-cone LCP"), std::string::npos);
    }
    EXPECT_NE(faceted_pgs.message.find("faceted cone with 8 facets"), std::string::npos);
    EXPECT_LT((faceted_pgs.solution - lemke.solution).lpNorm<Eigen::Infinity>(),
              1e-8 * std::max(1.0, lemke.solution.lpNorm<Eigen::Infinity>()));
  }
}

// In space the faceted cone's solution approaches the disk's as the facets multiply: the
// true (disk) residual of Lemke's answer falls with k (inscribed polygon error 1 − cos(π/k)).
TEST(FrictionLcpConversion, SpatialFacetedSolutionApproachesTheDisk) {
  const FrictionProblem problem = random_friction_problem({6, 12, 3, false, 17});
  double previous = 1.0;
  for (const int facets : {4, 16, 64}) {
    SolverOptions options = tight();
    options.cone_facets = facets;
    const SolverResult lemke = solve_friction(problem, "lemke", options);
    ASSERT_TRUE(lemke.solution.allFinite()) << lemke.message;
    EXPECT_LT(lemke.residual, previous) << facets << " facets";
    previous = lemke.residual;
  }
  EXPECT_LT(previous, 1e-2);
}

}  // namespace
}  // namespace impactbench::solvers
