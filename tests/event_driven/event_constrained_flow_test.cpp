// The constrained flow of one set of modes (constrained_flow.hpp) against closed forms on an
// incline of angle α (ground normal n = (−sin α, cos α), tangent t = (cos α, sin α) up the
// slope): a disk slipping down, whose centre accelerates by −g(sin α − μ cos α) t and whose
// spin by 2μ g cos α / r (friction μ m g cos α at arm r, I = m r²/2); and a box sticking, held by
// N = m g cos α and T = m g sin α, split between its corners by the torque balance.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/constrained_flow.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"

namespace impactbench::engines::event_driven {
namespace {

constexpr double kG = 9.81, kMass = 2.0;
const double kAngle = 0.4;  // [rad]

std::vector<model::Contact<double>> contacts_at(const test_support::PlanarTestWorld& world,
                                                const Eigen::VectorXd& q,
                                                const Eigen::VectorXd& v) {
  std::vector<model::Contact<double>> contacts;
  world.find_contacts(q, v, 1e-3, contacts);
  return contacts;
}

TEST(EventConstrainedFlow, DiskSlippingDownAnInclineDeceleratesByCoulombFriction) {
  const double mu = 0.3, r = 0.2;
  const test_support::PlanarTestWorld world({{"disk", kMass, r}}, kG, mu, 0.0, true, kAngle);
  const Eigen::Vector2d n = world.ground_normal(), t = world.ground_tangent();
  Eigen::VectorXd q(3), v(3);
  q << r * n, 0.0;
  v << -0.5 * t, 0.0;  // sliding down the slope, not spinning
  const auto contacts = contacts_at(world, q, v);
  ASSERT_EQ(contacts.size(), 1u);
  const double zeta_t = contacts[0].relative_velocity(v)[1];
  ASSERT_NEAR(zeta_t, -0.5, 1e-15);
  const std::vector<ClosedContact> closed = {
      {&contacts[0], ContactMode::kSlip, Eigen::VectorXd::Constant(1, -1.0)}};
  const DynamicsAtState dynamics(world, q, v, Eigen::VectorXd(0));
  const FlowSolution flow = solve_constrained_flow(dynamics, v, closed, EventDrivenOptions{});
  ASSERT_TRUE(flow.ok);
  const double scale = kG;
  const Eigen::Vector2d expected = -kG * (std::sin(kAngle) - mu * std::cos(kAngle)) * t;
  EXPECT_NEAR((flow.vdot.head<2>() - expected).norm(), 0.0, 1e-13 * scale);
  EXPECT_NEAR(flow.vdot[2], 2.0 * mu * kG * std::cos(kAngle) / r, 1e-13 * scale / r);
  const double normal_force = kMass * kG * std::cos(kAngle);
  EXPECT_NEAR(flow.forces[0].lambda_n, normal_force, 1e-13 * kMass * scale);
  // Friction opposes the sliding (up the slope, +t): λ_t = +μ λ_n.
  EXPECT_NEAR(flow.forces[0].lambda_t[0], mu * normal_force, 1e-13 * kMass * scale);
}

TEST(EventConstrainedFlow, BoxStickingOnAnInclineIsHeldWithTheTorqueBalancedSplit) {
  const double mu = 0.8, w = 0.6, h = 0.3;  // tan α = 0.42 < μ
  const test_support::PlanarTestWorld world({{"box", kMass, 0.0, w, h}}, kG, mu, 0.0, true, kAngle);
  Eigen::VectorXd q(3), v = Eigen::VectorXd::Zero(3);
  q << 0.5 * h * world.ground_normal(), kAngle;  // bottom face on the slope
  const auto contacts = contacts_at(world, q, v);
  ASSERT_EQ(contacts.size(), 2u);  // the two bottom corners: redundant tangential rows
  std::vector<ClosedContact> closed;
  for (const auto& c : contacts) closed.push_back({&c, ContactMode::kStick, Eigen::VectorXd()});
  const DynamicsAtState dynamics(world, q, v, Eigen::VectorXd(0));
  const FlowSolution flow = solve_constrained_flow(dynamics, v, closed, EventDrivenOptions{});
  ASSERT_TRUE(flow.ok);
  const double force = kMass * kG, tol = 1e-12 * force;
  EXPECT_NEAR(flow.vdot.norm(), 0.0, 1e-12 * kG);
  // Corner 0 is the lower one (x = −w/2 along the slope). Moments about the centre:
  // (w/2)(N₁ − N₀) + (h/2)(T₀ + T₁) = 0, with N₀ + N₁ = m g cos α and T₀ + T₁ = m g sin α.
  const double N = force * std::cos(kAngle), T = force * std::sin(kAngle);
  const double n0 = 0.5 * (N + (h / w) * T), n1 = 0.5 * (N - (h / w) * T);
  EXPECT_NEAR(flow.forces[0].lambda_n, n0, tol);
  EXPECT_NEAR(flow.forces[1].lambda_n, n1, tol);
  // The tangential force, undetermined by the rigid body, is spread in proportion to the
  // corners' friction capacity μ N_i: T_i = T N_i / N.
  EXPECT_NEAR(flow.forces[0].lambda_t[0], T * n0 / N, tol);
  EXPECT_NEAR(flow.forces[1].lambda_t[0], T * n1 / N, tol);
}

TEST(EventConstrainedFlow, RedundantRowsShareTheLoadAndContradictoryOnesHaveNoFlow) {
  const double r = 0.2;
  const test_support::PlanarTestWorld world({{"disk", kMass, r}}, kG, 0.5, 0.0, true, 0.0);
  Eigen::VectorXd q(3), v = Eigen::VectorXd::Zero(3);
  q << 0.0, r, 0.0;
  const auto contacts = contacts_at(world, q, v);
  ASSERT_EQ(contacts.size(), 1u);
  const DynamicsAtState dynamics(world, q, v, Eigen::VectorXd(0));
  // The same contact closed twice: D has rank 2 of 4 but D λ = b is consistent. v̇ = 0, and
  // the least weighted norm shares the weight m g equally.
  const std::vector<ClosedContact> twice = {{&contacts[0], ContactMode::kStick, {}},
                                            {&contacts[0], ContactMode::kStick, {}}};
  const FlowSolution flow = solve_constrained_flow(dynamics, v, twice, EventDrivenOptions{});
  EXPECT_TRUE(flow.ok);
  EXPECT_NEAR(flow.vdot.norm(), 0.0, 1e-12 * kG);
  for (const ContactForce& f : flow.forces) EXPECT_NEAR(f.lambda_n, 0.5 * kMass * kG, 1e-12 * kG);
  // The same rows asking for different normal accelerations (drifts 0 and 1 m/s²): no flow.
  model::Contact<double> drifting = contacts[0];
  drifting.normal_drift = 1.0;
  const std::vector<ClosedContact> contradictory = {{&contacts[0], ContactMode::kStick, {}},
                                                    {&drifting, ContactMode::kStick, {}}};
  EXPECT_FALSE(solve_constrained_flow(dynamics, v, contradictory, EventDrivenOptions{}).ok);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
