// The spatial one-contact solve in vectors of fixed size (nsgs's local step in space): closed
// forms where the block is decoupled, and the local problem's complementarity where it is not.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "solvers/friction/coulomb_cone.hpp"
#include "solvers/friction/single_contact_solver.hpp"

namespace impactbench::solvers {
namespace {

// The natural-map residual of u = A r + b, K_μ ∋ r ⊥ u + μ‖u_t‖ e_n ∈ K_μ*, relative to the
// size of r and b: r − Π_K(r − (u + μ‖u_t‖ e_n)), zero exactly at a solution.
double relative_residual(const Eigen::Matrix3d& a, const Eigen::Vector3d& b, double mu,
                         const Eigen::Vector3d& r) {
  Eigen::Vector3d shifted = a * r + b;
  shifted(0) += mu * shifted.tail<2>().norm();
  const Eigen::Vector3d projected = project_on_coulomb_cone_of(mu, Eigen::Vector3d(r - shifted));
  return (r - projected).norm() / (r.norm() + b.norm() / a(0, 0));
}

TEST(SingleContactSpatial, OpenContactTakesNoImpulse) {
  const Eigen::Matrix3d a = Eigen::Vector3d(2.0, 3.0, 3.0).asDiagonal();
  Eigen::Vector3d r(1.0, 0.2, -0.3);  // a start that must not survive
  ASSERT_TRUE(solve_single_contact_spatial(a, Eigen::Vector3d(0.5, -4.0, 1.0), 0.4, r));
  EXPECT_EQ(r, Eigen::Vector3d::Zero());
}

TEST(SingleContactSpatial, StickInsideTheConeCancelsTheVelocity) {
  // A decoupled: r = −A⁻¹ b = (2, 0.1, −0.05), inside the cone of μ = 0.5 (‖r_t‖ ≈ 0.112).
  const Eigen::Matrix3d a = Eigen::Vector3d(2.0, 4.0, 4.0).asDiagonal();
  const Eigen::Vector3d b(-4.0, -0.4, 0.2);
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  ASSERT_TRUE(solve_single_contact_spatial(a, b, 0.5, r));
  EXPECT_NEAR(r(0), 2.0, 1e-15);
  EXPECT_NEAR(r(1), 0.1, 1e-15);
  EXPECT_NEAR(r(2), -0.05, 1e-15);
}

TEST(SingleContactSpatial, SlipOnADecoupledBlockHasTheClosedForm) {
  // A = diag(a_n, a_t, a_t): u_n = 0 gives r_n = −b_n / a_n; sliding, r_t = −μ r_n b_t/‖b_t‖
  // and u_t = b_t (1 − a_t μ r_n / ‖b_t‖), along b_t when ‖b_t‖ > a_t μ r_n (here 5 > 1.2).
  const double a_n = 2.0, a_t = 3.0, mu = 0.4;
  const Eigen::Matrix3d a = Eigen::Vector3d(a_n, a_t, a_t).asDiagonal();
  const Eigen::Vector3d b(-2.0, 3.0, -4.0);
  Eigen::Vector3d r(1.0, 0.0, 0.0);
  ASSERT_TRUE(solve_single_contact_spatial(a, b, mu, r));
  const double r_n = -b(0) / a_n;
  const Eigen::Vector2d r_t = -mu * r_n * b.tail<2>() / b.tail<2>().norm();
  EXPECT_NEAR(r(0), r_n, 1e-14);
  EXPECT_NEAR(r(1), r_t(0), 1e-14);
  EXPECT_NEAR(r(2), r_t(1), 1e-14);
}

TEST(SingleContactSpatial, AnImpulseReportedExactSolvesTheLocalProblemInEveryCase) {
  std::mt19937 random(20261129);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  std::uniform_real_distribution<double> friction(0.05, 1.5);
  int open = 0, stick = 0, slip = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    // A = J M⁻¹ Jᵀ of one contact: symmetric positive definite, the local frame's rows coupled.
    Eigen::Matrix3d j;
    for (int k = 0; k < 9; ++k) j(k / 3, k % 3) = entry(random);
    const Eigen::Matrix3d a = j * j.transpose() + 1e-2 * Eigen::Matrix3d::Identity();
    const double mu = friction(random);
    const Eigen::Vector3d b(entry(random), 2.0 * entry(random), 2.0 * entry(random));
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    // The solve may report that it fell short (its Newton does on a few strongly coupled
    // blocks); what it reports exact must be a solution.
    if (!solve_single_contact_spatial(a, b, mu, r)) continue;
    ASSERT_LE(relative_residual(a, b, mu, r), 1e-12) << trial;
    if (r.isZero(0.0))
      ++open;
    else if (r.tail<2>().norm() < mu * r(0) * (1.0 - 1e-9))
      ++stick;
    else
      ++slip;
  }
  // Every case was solved exactly, a hundred times at least (the slips by the Newton).
  EXPECT_GE(open, 100);
  EXPECT_GE(stick, 100);
  EXPECT_GE(slip, 100);
}

TEST(SingleContactSpatial, TheGeneralEntryGivesTheSameImpulse) {
  // solve_single_contact with LocalVector hands d = 3 to the fixed-size solve, a start of the
  // wrong size as no start.
  const Eigen::Matrix3d a{{2.0, 0.3, -0.2}, {0.3, 1.5, 0.1}, {-0.2, 0.1, 1.8}};
  const Eigen::Vector3d b(-1.0, 2.5, -1.5);
  Eigen::Vector3d fixed(1.0, 0.0, 0.0);
  ASSERT_TRUE(solve_single_contact_spatial(a, b, 0.3, fixed));
  LocalVector general = Eigen::Vector3d(1.0, 0.0, 0.0);
  ASSERT_TRUE(solve_single_contact(a, b, 0.3, general));
  EXPECT_EQ(Eigen::Vector3d(general), fixed);
  LocalVector no_start(1);
  no_start << 5.0;
  ASSERT_TRUE(solve_single_contact(a, b, 0.3, no_start));
  ASSERT_EQ(no_start.size(), 3);
  EXPECT_LE(relative_residual(a, b, 0.3, no_start), 1e-12);
}

}  // namespace
}  // namespace impactbench::solvers
