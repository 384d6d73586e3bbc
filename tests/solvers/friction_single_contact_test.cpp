// One contact with closed-form solutions, through every solver of the registry.
#include <gtest/gtest.h>

#include "solvers/friction/friction_solvers.hpp"

namespace impactbench::solvers {
namespace {

SolverOptions tight() {
  SolverOptions options;
  options.tolerance = 1e-12;
  options.max_iterations = 2000;
  return options;
}

// The LCP solvers (lemke, pgs) are exact for the planar LCP form; the spatial faceted cone is
// exact only along its facets.
bool exact_for(const std::string& name, int dimension) {
  return !(dimension == 3 && (name == "lemke" || name == "pgs"));
}

// Spatial, decoupled W = diag(a, c, c), q = (b_n, b_t), b_n < 0: r_n = −b_n/a; stick
// r_t = −b_t/c when ‖b_t‖/c ≤ μ r_n. Here a = 2, c = 1, b = (−2, 0.3, −0.4), μ = 0.8:
// r_n = 1, ‖b_t‖ = 0.5 ≤ 0.8 → stick, r = (1, −0.3, 0.4), u = 0.
TEST(SingleContact, StickStrictlyInsideTheCone) {
  const Eigen::Matrix3d w = Eigen::Vector3d(2.0, 1.0, 1.0).asDiagonal();
  const FrictionProblem problem = FrictionProblem::dense(3, w, Eigen::Vector3d(-2.0, 0.3, -0.4),
                                                         Eigen::VectorXd::Constant(1, 0.8));
  for (const SolverInfo& info : friction_solvers()) {
    // The faceted cone contains this stick impulse too (octagon inradius 0.8 cos(π/8) > 0.5).

    SCOPED_TRACE(info.name);
    const SolverResult result = solve_friction(problem, info.name, tight());
    ASSERT_TRUE(result.converged()) << result.message;
    EXPECT_NEAR(result.solution(0), 1.0, 1e-10);
    EXPECT_NEAR(result.solution(1), -0.3, 1e-10);
    EXPECT_NEAR(result.solution(2), 0.4, 1e-10);
    EXPECT_LT(result.solution.tail(2).norm(), 0.8 * result.solution(0));  // strictly inside
    EXPECT_LT(result.velocity.norm(), 1e-10);
  }
}

// Same W, b_t = (3, −4), ‖b_t‖ = 5 > μ r_n c: slip with r_t = −μ r_n b_t/‖b_t‖ = (−0.48, 0.64),
// u_t = c r_t + b_t = 4.2 · b_t/5: the friction impulse opposes the sliding velocity and
// dissipates the most possible power, r_t·u_t = −μ r_n ‖u_t‖.
TEST(SingleContact, SlipOnTheBoundaryOpposesSlidingVelocity) {
  const Eigen::Matrix3d w = Eigen::Vector3d(2.0, 1.0, 1.0).asDiagonal();
  const FrictionProblem problem = FrictionProblem::dense(3, w, Eigen::Vector3d(-2.0, 3.0, -4.0),
                                                         Eigen::VectorXd::Constant(1, 0.8));
  for (const SolverInfo& info : friction_solvers()) {
    if (!exact_for(info.name, 3)) continue;
    SCOPED_TRACE(info.name);
    const SolverResult result = solve_friction(problem, info.name, tight());
    ASSERT_TRUE(result.converged()) << result.message;
    EXPECT_NEAR(result.solution(0), 1.0, 1e-10);
    EXPECT_NEAR(result.solution(1), -0.48, 1e-10);
    EXPECT_NEAR(result.solution(2), 0.64, 1e-10);
    EXPECT_NEAR(result.velocity(0), 0.0, 1e-10);
    EXPECT_NEAR(result.velocity(1), 3.0 * 4.2 / 5.0, 1e-10);
    EXPECT_NEAR(result.velocity(2), -4.0 * 4.2 / 5.0, 1e-10);
    const double power = result.solution.tail(2).dot(result.velocity.tail(2));
    EXPECT_NEAR(power, -0.8 * result.solution(0) * result.velocity.tail(2).norm(), 1e-10);
  }
}

// Planar with coupling W = [[2, 0.5], [0.5, 1]], q = (−1, 3), μ = 0.5. Stick would need
// r = −W⁻¹q = (2.5, −6.5)/1.75, outside the cone. Slip with u_t > 0: r_t = −μ r_n and
// u_n = (2 − 0.5·0.5) r_n − 1 = 0 ⇒ r_n = 1/1.75, r_t = −0.5/1.75,
// u_t = 0.5 r_n + r_t + 3 = 3 > 0 (consistent).
TEST(SingleContact, PlanarCoupledSlipClosedForm) {
  Eigen::Matrix2d w;
  w << 2.0, 0.5, 0.5, 1.0;
  const FrictionProblem problem =
      FrictionProblem::dense(2, w, Eigen::Vector2d(-1.0, 3.0), Eigen::VectorXd::Constant(1, 0.5));
  for (const SolverInfo& info : friction_solvers()) {
    if (!exact_for(info.name, 2)) continue;
    SCOPED_TRACE(info.name);
    const SolverResult result = solve_friction(problem, info.name, tight());
    ASSERT_TRUE(result.converged()) << result.message;
    EXPECT_NEAR(result.solution(0), 1.0 / 1.75, 1e-10);
    EXPECT_NEAR(result.solution(1), -0.5 / 1.75, 1e-10);
    EXPECT_NEAR(result.velocity(1), 3.0, 1e-10);
  }
}

// Separating contact: q_n > 0 ⇒ r = 0, u = q.
TEST(SingleContact, OpenContactCarriesNoImpulse) {
  const FrictionProblem problem =
      FrictionProblem::dense(3, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 1.0, 2.0),
                             Eigen::VectorXd::Constant(1, 0.3));
  for (const SolverInfo& info : friction_solvers()) {
    SCOPED_TRACE(info.name);
    const SolverResult result = solve_friction(problem, info.name, tight());
    ASSERT_TRUE(result.converged()) << result.message;
    EXPECT_EQ(result.solution.norm(), 0.0);
    EXPECT_EQ(result.iterations, 0);  // r = 0 already solves it: the driver's trivial case
  }
}

// pgs on the friction LCP works by contact blocks: the scalar update would divide by M_ββ = 0
// (w_β = μ r_n − Σα does not involve β). W = I, q = (−1, 3), μ = 0.5: r_n = 1 and slip,
// r_t = −μ r_n = −0.5 (opposing u_t = 2.5), reached in one sweep since the one block is exact.
TEST(SingleContact, PgsSolvesTheZeroDiagonalLcpByBlocks) {
  const FrictionProblem problem =
      FrictionProblem::dense(2, Eigen::Matrix2d::Identity(), Eigen::Vector2d(-1.0, 3.0),
                             Eigen::VectorXd::Constant(1, 0.5));
  const SolverResult result = solve_friction(problem, "pgs", tight());
  ASSERT_TRUE(result.converged()) << result.message;
  EXPECT_NEAR(result.solution(0), 1.0, 1e-12);
  EXPECT_NEAR(result.solution(1), -0.5, 1e-12);
  EXPECT_NEAR(result.velocity(1), 2.5, 1e-12);
  EXPECT_EQ(result.iterations, 1);
}

}  // namespace
}  // namespace impactbench::solvers
