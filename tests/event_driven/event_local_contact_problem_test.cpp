// The local contact problem u = W r + q (local_contact_problem.hpp) on hand-solved cases.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/local_contact_problem.hpp"

namespace impactbench::engines::event_driven {
namespace {

LocalContactProblem planar(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& mu, std::vector<bool> coulomb) {
  LocalContactProblem p;
  p.tangent_dim = 1;
  p.W = W;
  p.q = q;
  p.mu = mu;
  p.coulomb = std::move(coulomb);
  return p;
}

// One planar contact with W = [2 1; 1 2] (normal and tangent coupled), solved.
LocalContactSolution solve_coupled(const Eigen::Vector2d& q, double mu) {
  Eigen::MatrixXd W(2, 2);
  W << 2, 1, 1, 2;
  const LocalContactSolution s = solve_local_contact_problem(
      planar(W, q, Eigen::VectorXd::Constant(1, mu), {true}), EventDrivenOptions{});
  EXPECT_TRUE(s.ok()) << s.message;
  return s;
}

TEST(EventLocalContactProblem, OnePlanarContactSlidesWhenStickingExceedsTheCone) {
  // W = [2 1; 1 2], q = (−2, 3), μ = 1/2. Stick (u = 0): r = −W⁻¹q = (7/3, −8/3), outside the
  // cone (8/3 > 7/6). Slip with u_t > 0: r_t = −μ r_n and u_n = 2 r_n + r_t − 2 = 0 give
  // r = (4/3, −2/3), u_t = r_n + 2 r_t + 3 = 3 > 0: friction opposes the sliding.
  const LocalContactSolution s = solve_coupled(Eigen::Vector2d(-2, 3), 0.5);
  EXPECT_NEAR(s.r[0], 4.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.r[1], -2.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.u[0], 0.0, 1e-12);
  EXPECT_NEAR(s.u[1], 3.0, 1e-12);
}

TEST(EventLocalContactProblem, OnePlanarContactSticksInsideTheCone) {
  // Same W, q = (−3, 0.6), μ = 0.8: r = −W⁻¹q with W⁻¹ = (1/3)[2 −1; −1 2] is (2.2, −1.4), and
  // |r_t| = 1.4 ≤ μ r_n = 1.76: stick, u = 0.
  const LocalContactSolution s = solve_coupled(Eigen::Vector2d(-3, 0.6), 0.8);
  EXPECT_NEAR(s.r[0], 2.2, 1e-12);
  EXPECT_NEAR(s.r[1], -1.4, 1e-12);
  EXPECT_NEAR(s.u.norm(), 0.0, 1e-12);
}

TEST(EventLocalContactProblem, TwoNormalOnlyContactsOneOfWhichOpens) {
  // Normal rows W_nn = [2 1; 1 2], q_n = (−1, 1). Both closed: r_n = −W_nn⁻¹ q_n = (1, −1),
  // infeasible. Contact 2 open: r_n1 = 1/2, u_n2 = 1·(1/2) + 1 = 3/2 ≥ 0. The tangential
  // rows only report u_t = W_tn r_n + q_t (normal-only: r_t = 0).
  Eigen::MatrixXd W = Eigen::MatrixXd::Identity(4, 4);
  W(0, 2) = W(2, 0) = 1.0;
  W(0, 0) = W(2, 2) = 2.0;
  W(1, 0) = 0.4;  // u_t1 depends on r_n1
  Eigen::VectorXd q(4);
  q << -1, 0.1, 1, -0.2;
  const auto p = planar(W, q, Eigen::Vector2d(0.5, 0.5), {false, false});
  const LocalContactSolution s = solve_local_contact_problem(p, EventDrivenOptions{});
  ASSERT_TRUE(s.ok()) << s.message;
  Eigen::VectorXd r(4), u(4);
  r << 0.5, 0, 0, 0;
  u << 0, 0.1 + 0.4 * 0.5, 1.5, -0.2;
  EXPECT_NEAR((s.r - r).norm(), 0.0, 1e-12);
  EXPECT_NEAR((s.u - u).norm(), 0.0, 1e-12);
}

TEST(EventLocalContactProblem, OneSpatialContactSlidesAgainstItsTangentialVelocity) {
  // W = I, q = (−1, 3, 4), μ = 1/2: stick would need ‖r_t‖ = 5 > μ r_n = 1/2. Sliding: r_n = 1
  // (u_n = 0), r_t = −μ r_n (3, 4)/5 = (−0.3, −0.4), u_t = (2.7, 3.6) ∥ −r_t.
  LocalContactProblem p;
  p.tangent_dim = 2;
  p.W = Eigen::MatrixXd::Identity(3, 3);
  p.q = Eigen::Vector3d(-1, 3, 4);
  p.mu = Eigen::VectorXd::Constant(1, 0.5);
  p.coulomb = {true};
  const EventDrivenOptions options;
  const LocalContactSolution s = solve_local_contact_problem(p, options);
  ASSERT_TRUE(s.ok()) << s.message;
  // The friction solver stops at solver_tolerance relative to 1 + ‖q‖∞ = 5.
  const double tol = 10.0 * options.solver_tolerance * 5.0;
  EXPECT_NEAR((s.r - Eigen::Vector3d(1, -0.3, -0.4)).norm(), 0.0, tol);
  EXPECT_NEAR((s.u - Eigen::Vector3d(0, 2.7, 3.6)).norm(), 0.0, tol);
}

// The impulse-level problem of the plank–box's second impact (corner C_R lands while C_L
// slides), as the event engine met it with method = bdf: the corners' tangents are nearly
// parallel (W's tangential block is singular to 1e-10), and Lemke's method stops on a secondary
// ray although the problem has a solution. Order (n_L, t_L, n_R, t_R).
LocalContactProblem plank_box_second_impact() {
  Eigen::MatrixXd W(4, 4);
  W << 3.6398657376778445, -1.2059980217690729, -1.0401738301807228, -1.2059980213177792,
      -1.2059980217690729, 1.6001499852329306, 1.1910022786637913, 1.6001499850017891,
      -1.0401738301807228, 1.1910022786637913, 3.9397806025606492, 1.191002278183577,
      -1.205998021317779, 1.6001499850017891, 1.191002278183577, 1.6001499847706477;
  Eigen::VectorXd q(4);
  q << -1.1102230246251565e-16, -0.030940215818966818, -1.8129706459672121, -0.030940215644143051;
  return planar(W, q, Eigen::Vector2d(0.5, 0.5), {true, true});
}

TEST(EventLocalContactProblem, AProblemLemkeStopsOnIsSolvedByEnumeration) {
  const LocalContactProblem p = plank_box_second_impact();
  EventDrivenOptions options;
  options.lcp_solver = "lemke";
  const LocalContactSolution s = solve_local_contact_problem(p, options);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_TRUE(s.enumerated);  // Lemke failed: the premise of the case
  EXPECT_NE(s.message.find("lemke stopped"), std::string::npos) << s.message;
  // Coulomb's law contact by contact, checked on r and u (not on the LCP's unknowns): closed
  // (r_n > 0, u_n = 0), sliding on the cone's edge against the tangential velocity.
  const double tol = 10.0 * options.solver_tolerance * (1.0 + p.q.cwiseAbs().maxCoeff());
  EXPECT_NEAR((s.u - (p.W * s.r + p.q)).norm(), 0.0, 1e-14);
  for (int i = 0; i < 2; ++i) {
    SCOPED_TRACE(i);
    const double r_n = s.r[2 * i], r_t = s.r[2 * i + 1], u_n = s.u[2 * i], u_t = s.u[2 * i + 1];
    EXPECT_GT(r_n, 0.0);
    EXPECT_NEAR(u_n, 0.0, tol);
    EXPECT_NEAR(std::abs(r_t), p.mu[i] * r_n, tol);
    EXPECT_GT(u_t, tol);
    EXPECT_LT(r_t, 0.0);
  }
}

TEST(EventLocalContactProblem, EnumerationAsTheLcpSolverHasNoFallback) {
  EventDrivenOptions options;
  options.lcp_solver = "enum";
  const LocalContactSolution s = solve_local_contact_problem(plank_box_second_impact(), options);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_FALSE(s.enumerated);
}

TEST(EventLocalContactProblem, AProblemWithoutSolutionFailsWithBothReasons) {
  // W_nn = −1, q_n = −1: u_n = −r_n − 1 < 0 for every r_n ≥ 0 (no solution). Lemke ends on a ray,
  // enumeration finds no basis; the message gives both, and the solution is not ok.
  Eigen::MatrixXd W = Eigen::MatrixXd::Identity(2, 2);
  W(0, 0) = -1.0;
  EventDrivenOptions options;
  options.lcp_solver = "lemke";
  const LocalContactSolution s = solve_local_contact_problem(
      planar(W, Eigen::Vector2d(-1, 0), Eigen::VectorXd::Constant(1, 0.5), {false}), options);
  EXPECT_FALSE(s.ok());
  EXPECT_FALSE(s.enumerated);
  EXPECT_NE(s.message.find("enumeration: no complementary basis"), std::string::npos) << s.message;
}

TEST(EventLocalContactProblem, InconsistentSizesAreRejected) {
  LocalContactProblem p;
  p.W = Eigen::MatrixXd::Identity(2, 2);
  p.q = Eigen::VectorXd::Zero(3);
  p.mu = Eigen::VectorXd::Constant(1, 0.5);
  p.coulomb = {true};
  EXPECT_THROW(solve_local_contact_problem(p, EventDrivenOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
