// The acceleration-level mode decision (mode_consistency.hpp) on a disk at rest on an incline
// of angle α: rolling needs the friction f = m g sin α / 3 (from m a = m g sin α − f and
// I a / r = f r with I = m r²/2), so Coulomb's inequality f ≤ μ m g cos α decides: stick
// (rolling, the contact point at rest) when tan α ≤ 3μ, slip otherwise, the contact point then
// accelerating down the slope by g (sin α − 3μ cos α).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/mode_consistency.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"

namespace impactbench::engines::event_driven {
namespace {

constexpr double kG = 9.81, kMass = 1.5, kRadius = 0.25, kMu = 0.2;

// The decision for the disk at rest on the incline with tan α = ratio · 3μ, whose normal force
// must be m g cos α whatever the mode.
ModeDecision decide_on_incline(double ratio) {
  const double angle = std::atan(ratio * 3.0 * kMu);
  const test_support::PlanarTestWorld world({{"disk", kMass, kRadius}}, kG, kMu, 0.0, true, angle);
  Eigen::VectorXd q(3), v = Eigen::VectorXd::Zero(3);
  q << kRadius * world.ground_normal(), 0.0;
  std::vector<model::Contact<double>> contacts;
  world.find_contacts(q, v, 1e-3, contacts);
  std::vector<ModeCandidate> candidates(1);
  candidates[0].contact = &contacts.at(0);
  const DynamicsAtState dynamics(world, q, v, Eigen::VectorXd(0));
  const ModeConsistencyResult result =
      make_modes_consistent(dynamics, v, candidates, EventDrivenOptions{});
  EXPECT_TRUE(result.ok) << result.message;
  EXPECT_NEAR(result.decisions.at(0).lambda_n, kMass * kG * std::cos(angle), 1e-12 * kMass * kG);
  return result.decisions.at(0);
}

TEST(EventModeConsistency, DiskRollsWhenCoulombHoldsTheRollingFriction) {
  const double ratio = 0.9, angle = std::atan(ratio * 3.0 * kMu);
  const ModeDecision d = decide_on_incline(ratio);
  EXPECT_EQ(d.mode, ContactMode::kStick);
  // Up the slope (+t, the contact's tangent), a third of the weight's component along it.
  EXPECT_NEAR(d.lambda_t[0], kMass * kG * std::sin(angle) / 3.0, 1e-12 * kMass * kG);
  EXPECT_NEAR(d.accel_n, 0.0, 1e-12 * kG);
  EXPECT_NEAR(d.accel_t[0], 0.0, 1e-12 * kG);
}

TEST(EventModeConsistency, DiskSlipsWhenRollingWouldNeedMoreThanMuN) {
  const double ratio = 1.1, angle = std::atan(ratio * 3.0 * kMu);
  const ModeDecision d = decide_on_incline(ratio);
  EXPECT_EQ(d.mode, ContactMode::kSlip);
  // Saturated, up the slope.
  EXPECT_NEAR(d.lambda_t[0], kMu * kMass * kG * std::cos(angle), 1e-12 * kMass * kG);
  // The contact point slips down the slope (−t), the direction it tends to.
  EXPECT_NEAR(d.accel_t[0], -kG * (std::sin(angle) - 3.0 * kMu * std::cos(angle)), 1e-12 * kG);
  ASSERT_EQ(d.slip_reference.size(), 1);
  EXPECT_EQ(d.slip_reference[0], -1.0);
}

TEST(EventModeConsistency, ALiftoffHintOpensAContactThatIsPulledAway) {
  // A disk on level ground pulled up by 2 m g: the lift-off hint is honoured (a_n = g > 0).
  test_support::PlanarTestWorld world({{"disk", kMass, kRadius}}, kG, kMu, 0.0);
  world.add_input(0, Eigen::Vector2d::UnitY());
  Eigen::VectorXd q(3), v = Eigen::VectorXd::Zero(3);
  q << 0.0, kRadius, 0.0;
  std::vector<model::Contact<double>> contacts;
  world.find_contacts(q, v, 1e-3, contacts);
  std::vector<ModeCandidate> candidates(1);
  candidates[0].contact = &contacts.at(0);
  candidates[0].hint = ModeCandidate::Hint::kPreferOpen;
  const DynamicsAtState dynamics(world, q, v, Eigen::VectorXd::Constant(1, 2.0 * kMass * kG));
  const ModeConsistencyResult result =
      make_modes_consistent(dynamics, v, candidates, EventDrivenOptions{});
  ASSERT_TRUE(result.ok);
  EXPECT_EQ(result.decisions[0].mode, ContactMode::kOpen);
  EXPECT_NEAR(result.decisions[0].accel_n, kG, 1e-12 * kG);
  // Without the pull the hint would make it penetrate (a_n = −g): it is dropped, the disk rests.
  const DynamicsAtState resting(world, q, v, Eigen::VectorXd::Zero(1));
  const ModeConsistencyResult held =
      make_modes_consistent(resting, v, candidates, EventDrivenOptions{});
  ASSERT_TRUE(held.ok);
  EXPECT_NE(held.decisions[0].mode, ContactMode::kOpen);
  EXPECT_NEAR(held.decisions[0].lambda_n, kMass * kG, 1e-12 * kMass * kG);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
