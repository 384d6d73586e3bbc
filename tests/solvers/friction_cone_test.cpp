// Coulomb cone projection (three cases) and the FCLIB residual measure.
#include <cmath>
#include <random>
#include <utility>

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
  EXPECT_NEAR(friction_residual(problem, Eigen::VectorXd(Eigen::Vector3d(1.0, -0.5, 0.0))), 0.0,
              1e-15);
  EXPECT_GT(friction_residual(problem, Eigen::VectorXd(Eigen::Vector3d(1.0, 0.5, 0.0))), 0.1);
  EXPECT_GT(friction_residual(problem, Eigen::VectorXd(Eigen::Vector3d::Zero())), 0.1);
}

TEST(FrictionResidual, SpatialTermsAreThoseOfTheConeProjectionToTheBit) {
  // The residual's spatial terms are formed in scalars: they must be, to the bit, the FCLIB
  // measure formed with the vector projection, over points in all three of its cases (inside,
  // apex, boundary ray), zero tangents and μ = 0 among them.
  constexpr int kContacts = 3000;
  std::mt19937 rng(5);
  std::normal_distribution<double> n01;
  Eigen::VectorXd q(3 * kContacts), mu(kContacts), r(3 * kContacts), u(3 * kContacts);
  for (int i = 0; i < kContacts; ++i) {
    mu(i) = i % 11 == 0 ? 0.0 : std::abs(n01(rng));
    for (int k = 0; k < 3; ++k) {
      q(3 * i + k) = n01(rng);
      r(3 * i + k) = n01(rng);
      u(3 * i + k) = n01(rng);
    }
    if (i % 4 == 1) r(3 * i) = -4.0 - std::abs(n01(rng));  // mostly in the polar cone
    if (i % 4 == 2) {                                      // z_t = 0 and z_n > 0 mostly: inside
      r(3 * i) = 4.0 + std::abs(n01(rng));
      r.segment<2>(3 * i + 1) = u.segment<2>(3 * i + 1);
    }
    if (i % 13 == 0) r.segment<2>(3 * i + 1).setZero();
    if (i % 17 == 0) u.segment<2>(3 * i + 1).setZero();
  }
  double sum_of_squares = 0.0;
  int cases[3] = {0, 0, 0};  // inside, apex, boundary ray
  for (int i = 0; i < kContacts; ++i) {
    const LocalVector r_i = r.segment<3>(3 * i), u_i = u.segment<3>(3 * i);
    LocalVector z = r_i - u_i;  // r − (u + g(u)), g(u) = μ‖u_t‖ e_n
    z(0) = r_i(0) - (u_i(0) + mu(i) * u_i.tail(2).norm());
    const LocalVector projected = project_on_coulomb_cone(mu(i), z);
    cases[projected == z ? 0 : projected.isZero(0.0) ? 1 : 2] += 1;
    for (int k = 0; k < 3; ++k) sum_of_squares += (r_i(k) - projected(k)) * (r_i(k) - projected(k));
  }
  for (int count : cases) EXPECT_GT(count, kContacts / 10);
  Eigen::SparseMatrix<double, Eigen::RowMajor> identity(3 * kContacts, 3 * kContacts);
  identity.setIdentity();  // W does not enter the residual of given r and u
  const FrictionProblem problem = FrictionProblem::sparse(3, std::move(identity), q, mu);
  EXPECT_EQ(friction_residual(problem, r, u), std::sqrt(sum_of_squares) / q.norm());
  // The divisor a solver forms once per solve, and the residual given it.
  EXPECT_EQ(residual_scale(problem), q.norm());
  EXPECT_EQ(friction_residual(problem, r, u, residual_scale(problem)),
            std::sqrt(sum_of_squares) / q.norm());
}

TEST(FrictionResidual, DividesByOneWhenQIsZero) {
  const FrictionProblem problem = FrictionProblem::dense(
      2, Eigen::Matrix2d::Identity(), Eigen::Vector2d::Zero(), Eigen::VectorXd::Constant(1, 0.5));
  // r = (−1, 0) is outside the cone: r − Π_K(r − u) = (−1, 0) − Π_K((−2, 0)) = (−1, 0).
  EXPECT_NEAR(friction_residual(problem, Eigen::VectorXd(Eigen::Vector2d(-1.0, 0.0))), 1.0, 1e-15);
  EXPECT_EQ(residual_scale(problem), 1.0);
}

}  // namespace
}  // namespace impactbench::solvers
