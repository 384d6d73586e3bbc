// Friction solvers on random well-posed problems: convergence to the FCLIB residual, agreement
// between independent methods, warm starts, the registry and bad input.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "solvers/friction/friction_solvers.hpp"
#include "tests/support/solvers/independent_friction_residual.hpp"
#include "tests/support/solvers/random_friction_problem.hpp"
#include "tests/support/solvers/same_result.hpp"

namespace impactbench::solvers {
namespace {

SolverOptions options_with(double tolerance, int max_iterations) {
  SolverOptions options;
  options.tolerance = tolerance;
  options.max_iterations = max_iterations;
  return options;
}

FrictionProblem spatial_problem(int contacts, std::uint32_t seed, bool sparse = false) {
  return random_friction_problem({contacts, 2 * contacts, 3, sparse, seed});
}

class RandomSpatialProblems : public ::testing::TestWithParam<int> {};

TEST_P(RandomSpatialProblems, IndependentSolversConvergeAndAgree) {
  const int contacts = GetParam();
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const FrictionProblem problem = spatial_problem(contacts, seed);
    const SolverOptions options = options_with(1e-10, 20000);
    const SolverResult nsgs = solve_friction(problem, "nsgs", options);
    const SolverResult nsn = solve_friction(problem, "nsn", options);
    const SolverResult prox = solve_friction(problem, "prox-gs", options);
    for (const SolverResult* result : {&nsgs, &nsn, &prox}) {
      ASSERT_TRUE(result->converged()) << result->message;
      EXPECT_LT(result->residual, 1e-8);
      // The residual recomputed by the test's own formula, not the solvers' residual code.
      const double independent =
          test_support::independent_friction_residual(problem, result->solution);
      EXPECT_LT(independent, 1e-8);
      EXPECT_NEAR(independent, result->residual,
                  test_support::residual_allowance_for_velocity(problem, result->solution,
                                                                result->velocity));
    }
    const double scale = std::max(1.0, nsgs.solution.lpNorm<Eigen::Infinity>());
    EXPECT_LT((nsn.solution - nsgs.solution).lpNorm<Eigen::Infinity>(), 1e-6 * scale);
    EXPECT_LT((prox.solution - nsgs.solution).lpNorm<Eigen::Infinity>(), 1e-6 * scale);
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, RandomSpatialProblems, ::testing::Values(1, 5, 20, 100));

TEST(FrictionSolvers, PlanarRandomProblemsAgree) {
  const FrictionProblem problem = random_friction_problem({30, 60, 2, false, 7});
  const SolverOptions options = options_with(1e-10, 20000);
  const SolverResult nsgs = solve_friction(problem, "nsgs", options);
  ASSERT_TRUE(nsgs.converged()) << nsgs.message;
  for (const char* name : {"nsn", "prox-gs", "prox-jacobi"}) {
    SCOPED_TRACE(name);
    const SolverResult result = solve_friction(problem, name, options);
    ASSERT_TRUE(result.converged()) << result.message;
    EXPECT_LT((result.solution - nsgs.solution).lpNorm<Eigen::Infinity>(), 1e-6);
  }
}

TEST(FrictionSolvers, ProxJacobiConvergesOnASpatialProblem) {
  const FrictionProblem problem = spatial_problem(20, 11);
  const SolverResult result = solve_friction(problem, "prox-jacobi", options_with(1e-9, 50000));
  ASSERT_TRUE(result.converged()) << result.message;
  const SolverResult reference = solve_friction(problem, "nsgs", options_with(1e-11, 5000));
  EXPECT_LT((result.solution - reference.solution).lpNorm<Eigen::Infinity>(), 1e-6);
}

TEST(FrictionSolvers, SparseAndDenseGiveTheSameSolution) {
  const FrictionProblem dense = spatial_problem(40, 5, false);
  const FrictionProblem sparse = spatial_problem(40, 5, true);
  ASSERT_LT((Eigen::MatrixXd(sparse.sparse_W) - dense.dense_W).norm(), 1e-14);
  for (const char* name : {"nsgs", "nsn", "prox-gs"}) {
    SCOPED_TRACE(name);
    const SolverResult a = solve_friction(dense, name, options_with(1e-11, 20000));
    const SolverResult b = solve_friction(sparse, name, options_with(1e-11, 20000));
    ASSERT_TRUE(a.converged() && b.converged()) << a.message << " / " << b.message;
    EXPECT_LT((a.solution - b.solution).lpNorm<Eigen::Infinity>(), 1e-8);
  }
}

TEST(FrictionSolvers, WarmStartFromANearbyProblemCutsIterations) {
  const FrictionProblem original = spatial_problem(60, 21);
  FrictionProblem nearby = original;
  nearby.q *= 1.01;  // a 1 % change, like the next time step
  const SolverOptions options = options_with(1e-10, 20000);
  for (const char* name : {"nsgs", "prox-gs", "nsn"}) {
    SCOPED_TRACE(name);
    const SolverResult previous = solve_friction(original, name, options);
    ASSERT_TRUE(previous.converged()) << previous.message;
    const SolverResult cold = solve_friction(nearby, name, options);
    const SolverResult warm = solve_friction(nearby, name, options, &previous.solution);
    ASSERT_TRUE(cold.converged() && warm.converged());
    EXPECT_LT(warm.iterations, cold.iterations);
    EXPECT_LT((warm.solution - cold.solution).lpNorm<Eigen::Infinity>(), 1e-6);
  }
}

TEST(FrictionSolvers, IterationLimitIsReportedNotHidden) {
  const FrictionProblem problem = spatial_problem(100, 2);
  const SolverResult result = solve_friction(problem, "prox-jacobi", options_with(1e-14, 2));
  EXPECT_EQ(result.status, SolverStatus::kMaxIterations);
  EXPECT_FALSE(result.converged());
  EXPECT_GT(result.residual, 1e-14);
  EXPECT_EQ(result.iterations, 2);
}

// Turning the driver's timer off changes nothing but `seconds`, which says it was not measured.
TEST(FrictionSolvers, AnUntimedSolveHasTheSameAnswerAndNoTime) {
  const FrictionProblem problem = spatial_problem(4, 3);
  for (const SolverInfo& info : friction_solvers()) {
    SCOPED_TRACE(info.name);
    SolverOptions options = options_with(1e-8, 2000);
    const SolverResult timed = solve_friction(problem, info.name, options);
    options.measure_seconds = false;
    const SolverResult untimed = solve_friction(problem, info.name, options);
    expect_untimed_like_timed(untimed, timed);
  }
}

TEST(FrictionSolvers, RegistryListsEverySolverOnce) {
  std::vector<std::string> names;
  for (const SolverInfo& info : friction_solvers()) names.push_back(info.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"prox-jacobi", "prox-gs", "nsgs", "nsn", "lemke", "pgs"}));
}

TEST(FrictionSolversBadInput, UnknownNameThrows) {
  const FrictionProblem problem = spatial_problem(2, 1);
  EXPECT_THROW(solve_friction(problem, "gauss-newton"), std::invalid_argument);
}

TEST(FrictionSolversBadInput, NonFiniteDataIsRejectedBeforeSolving) {
  for (const SolverInfo& info : friction_solvers()) {
    SCOPED_TRACE(info.name);
    FrictionProblem problem = spatial_problem(3, 1);
    problem.q(4) = std::numeric_limits<double>::quiet_NaN();
    SolverResult result = solve_friction(problem, info.name);
    EXPECT_EQ(result.status, SolverStatus::kNonFiniteData);
    EXPECT_NE(result.message.find("q contains NaN"), std::string::npos) << result.message;

    problem = spatial_problem(3, 1);
    problem.dense_W(1, 2) = std::numeric_limits<double>::infinity();
    result = solve_friction(problem, info.name);
    EXPECT_EQ(result.status, SolverStatus::kNonFiniteData);
    EXPECT_NE(result.message.find("W contains"), std::string::npos) << result.message;
  }
}

// The finiteness check sums the values first; a sum that overflows must not make finite data
// look non-finite (the check then looks value by value).
TEST(FrictionSolversBadInput, FiniteValuesWhoseSumOverflowsAreNotCalledNonFinite) {
  constexpr double kHuge = 1e308;  // two of them sum to +inf
  FrictionProblem problem = spatial_problem(3, 1);
  problem.q(0) = kHuge;
  problem.q(3) = kHuge;
  problem.dense_W(1, 2) = problem.dense_W(2, 1) = kHuge;
  ASSERT_FALSE(std::isfinite(problem.q.sum()));
  for (const SolverInfo& info : friction_solvers()) {
    SCOPED_TRACE(info.name);
    const SolverResult result = solve_friction(problem, info.name);
    EXPECT_NE(result.status, SolverStatus::kNonFiniteData) << result.message;
    EXPECT_EQ(result.message.find("NaN or Inf"), std::string::npos) << result.message;
  }
}

TEST(FrictionSolversBadInput, NegativeFrictionCoefficientIsNamed) {
  FrictionProblem problem = spatial_problem(3, 1);
  problem.mu(2) = -0.1;
  const SolverResult result = solve_friction(problem, "nsgs");
  EXPECT_EQ(result.status, SolverStatus::kInvalidProblem);
  EXPECT_NE(result.message.find("mu of contact 2 is negative"), std::string::npos)
      << result.message;
}

TEST(FrictionSolversBadInput, InconsistentSizesAreRejected) {
  FrictionProblem problem = spatial_problem(3, 1);
  problem.q.conservativeResize(8);
  SolverResult result = solve_friction(problem, "nsn");
  EXPECT_EQ(result.status, SolverStatus::kInvalidProblem);
  EXPECT_NE(result.message.find("q has 8 entries"), std::string::npos) << result.message;

  problem = spatial_problem(3, 1);
  problem.dimension = 4;
  EXPECT_EQ(solve_friction(problem, "nsgs").status, SolverStatus::kInvalidProblem);

  problem = spatial_problem(3, 1);
  const Eigen::VectorXd short_start = Eigen::VectorXd::Zero(5);
  result = solve_friction(problem, "nsgs", {}, &short_start);
  EXPECT_EQ(result.status, SolverStatus::kInvalidProblem);
  EXPECT_NE(result.message.find("warm start"), std::string::npos);
}

TEST(FrictionSolversBadInput, VanishingNormalDiagonalIsSingular) {
  FrictionProblem problem =
      FrictionProblem::dense(3, Eigen::Vector3d(0.0, 1.0, 1.0).asDiagonal(),
                             Eigen::Vector3d(-1.0, 0.0, 0.0), Eigen::VectorXd::Constant(1, 0.5));
  for (const char* name : {"nsgs", "nsn", "prox-gs", "prox-jacobi"}) {
    SCOPED_TRACE(name);
    const SolverResult result = solve_friction(problem, name);
    EXPECT_EQ(result.status, SolverStatus::kSingular);
    EXPECT_NE(result.message.find("W_nn"), std::string::npos);
  }
}

}  // namespace
}  // namespace impactbench::solvers
