// Coulomb cone projection (three cases) and the FCLIB residual measure.
#include <random>

#include <gtest/gtest.h>

#include "solvers/friction/coulomb_cone.hpp"
#include "solvers/friction/friction_residual.hpp"

namespace impactbench::solvers {
namespace {

LocalVector vec3(double a, double b, double c) {
  LocalVector v(3);
  v << a, b, c;
  return v;
}

TEST(CoulombCone, PointInsideIsUnchanged) {
  const LocalVector x = vec3(2.0, 0.3, -0.4);  // ‖x_t‖ = 0.5 ≤ 0.5·2
  EXPECT_EQ(project_on_coulomb_cone(0.5, x), x);
}

TEST(CoulombCone, PointInPolarConeGoesToApex) {
  // Polar cone of K_μ: μ‖x_t‖ ≤ −x_n.
  EXPECT_EQ(project_on_coulomb_cone(0.5, vec3(-2.0, 1.0, 0.0)), LocalVector::Zero(3));
}

TEST(CoulombCone, PointOutsideGoesToBoundaryRay) {
  // μ = 1, x = (0, 2, 0): nearest point of the ray t(1, 1, 0) is t = 1.
  const LocalVector p = project_on_coulomb_cone(1.0, vec3(0.0, 2.0, 0.0));
  EXPECT_NEAR(p(0), 1.0, 1e-15);
  EXPECT_NEAR(p(1), 1.0, 1e-15);
  EXPECT_NEAR(p(2), 0.0, 1e-15);
}

TEST(CoulombCone, FrictionlessConeIsTheNormalRay) {
  const LocalVector p = project_on_coulomb_cone(0.0, vec3(1.5, 2.0, -1.0));
  EXPECT_EQ(p, vec3(1.5, 0.0, 0.0));
  EXPECT_EQ(project_on_coulomb_cone(0.0, vec3(-1.0, 0.0, 0.0)), LocalVector::Zero(3));
}

TEST(CoulombCone, ProjectionSatisfiesTheVariationalInequality) {
  // p = Π_K(x) ⇔ p ∈ K and ⟨x − p, y − p⟩ ≤ 0 for all y ∈ K; also Π is idempotent.
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> unit(-2.0, 2.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double mu = 0.1 + std::abs(unit(generator));
    const LocalVector x = vec3(unit(generator), unit(generator), unit(generator));
    const LocalVector p = project_on_coulomb_cone(mu, x);
    ASSERT_LE(p.tail(2).norm(), mu * p(0) + 1e-12);
    ASSERT_LE((project_on_coulomb_cone(mu, p) - p).norm(), 1e-12);
    for (int k = 0; k < 5; ++k) {
      LocalVector y = vec3(std::abs(unit(generator)), unit(generator), unit(generator));
      y = project_on_coulomb_cone(mu, y);
      ASSERT_LE((x - p).dot(y - p), 1e-10);
    }
  }
}

TEST(FrictionResidual, VanishesAtAnAnalyticSolutionAndNotElsewhere) {
  // One contact, W = I, q = (−1, 2, 0), μ = 0.5: slip solution r = (1, −0.5, 0), u = (0, 1.5, 0).
  const FrictionProblem problem =
      FrictionProblem::dense(3, Eigen::Matrix3d::Identity(), Eigen::Vector3d(-1.0, 2.0, 0.0),
                             Eigen::VectorXd::Constant(1, 0.5));
  EXPECT_NEAR(friction_residual(problem, Eigen::Vector3d(1.0, -0.5, 0.0)), 0.0, 1e-15);
  EXPECT_GT(friction_residual(problem, Eigen::Vector3d(1.0, 0.5, 0.0)), 0.1);
  EXPECT_GT(friction_residual(problem, Eigen::Vector3d::Zero()), 0.1);
}

TEST(FrictionResidual, DividesByOneWhenQIsZero) {
  const FrictionProblem problem = FrictionProblem::dense(
      2, Eigen::Matrix2d::Identity(), Eigen::Vector2d::Zero(), Eigen::VectorXd::Constant(1, 0.5));
  // r = (−1, 0) is outside the cone: r − Π_K(r − u) = (−1, 0) − Π_K((−2, 0)) = (−1, 0).
  EXPECT_NEAR(friction_residual(problem, Eigen::Vector2d(-1.0, 0.0)), 1.0, 1e-15);
}

}  // namespace
}  // namespace impactbench::solvers
