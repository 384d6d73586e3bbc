// The event-driven engine with the opt-in restart options (startup_order = 2: the step-growth
// limit lifted at order 2; dense_output_root_search: roots located on CVODE's dense output)
// keeps the bouncing ball's closed-form impact times and apex heights to the same bound as the
// default engine (event_planar_test.cpp), in fewer CVODE steps.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"
#include "tests/support/lib/bouncing_ball_impacts.hpp"

namespace impactbench::engines::event_driven {
namespace {

constexpr double g = 9.81;

EventDrivenResult drop_ball(const EventDrivenOptions& options) {
  // Ball of radius 0.1 dropped from a centre height of 1, restitution 0.9.
  const test_support::PlanarTestWorld world({{"ball", 1.0, 0.1}}, g, 0.0, 0.9);
  const EventDrivenIntegrator integrator(world, options);
  return integrator.simulate(Eigen::Vector3d(0, 1.0, 0), Eigen::Vector3d::Zero(), {}, 10.0);
}

TEST(EventFastRestart, KeepsTheBouncingBallsImpactTimesAndApexes) {
  EventDrivenOptions options;
  options.startup_order = 2;
  options.dense_output_root_search = true;
  const EventDrivenResult fast = drop_ball(options);
  ASSERT_TRUE(fast.succeeded()) << fast.message;
  const std::size_t checked =
      test_support::expect_closed_form_impacts(fast, {0.1, 0.9, 0.9, g}, 1e-9, /*max_impacts=*/20);
  EXPECT_EQ(checked, 20u);
  // The point of the options: a flight under gravity in fewer steps than the slow startup's.
  EXPECT_LT(fast.summary.steps, drop_ball({}).summary.steps);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
