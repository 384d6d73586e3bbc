// The event-driven integrator's API contract: invalid options and initial data are rejected
// with a message naming the problem, run-time limits are reported as statuses, and the events
// CSV / summary have the design's format.
#include <sstream>
#include <stdexcept>
#include <utility>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/engines/event_driven/event_log.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"
#include "tests/support/lib/error_message.hpp"

namespace impactbench::engines::event_driven {
namespace {

// A ball with one (unused) horizontal force input, so input sizes can be checked.
test_support::PlanarTestWorld bouncing_ball() {
  test_support::PlanarTestWorld world({{"ball", 1.0, 0.1}}, 9.81, 0.0, 0.5);
  world.add_input(0, Eigen::Vector2d::UnitX());
  return world;
}

template <typename F>
std::string error_of(F&& f) {
  return test_support::error_message_of<std::invalid_argument>(std::forward<F>(f));
}

TEST(EventDrivenApi, RejectsInvalidOptionsWithTheirName) {
  const auto ball = bouncing_ball();
  EventDrivenOptions o;
  o.relative_tolerance = 0.0;
  EXPECT_NE(error_of([&] { EventDrivenIntegrator(ball, o); }).find("relative_tolerance"),
            std::string::npos);
  o = {};
  o.zeno_impact_count = 0;
  EXPECT_NE(error_of([&] { EventDrivenIntegrator(ball, o); }).find("zeno_impact_count"),
            std::string::npos);
  o = {};
  o.startup_step_growth = 1.0;
  EXPECT_NE(error_of([&] { EventDrivenIntegrator(ball, o); }).find("startup_step_growth"),
            std::string::npos);
}

TEST(EventDrivenApi, RejectsANegativeStartupOrder) {
  EventDrivenOptions o;
  o.startup_order = -1;
  EXPECT_NE(error_of([&] { EventDrivenIntegrator(bouncing_ball(), o); }).find("startup_order"),
            std::string::npos);
}

TEST(EventDrivenApi, RejectsBadInitialDataAndInputs) {
  const auto ball = bouncing_ball();
  const EventDrivenIntegrator integrator(ball);
  const Eigen::Vector3d q(0, 1, 0), v = Eigen::Vector3d::Zero();
  EXPECT_NE(error_of([&] { integrator.simulate(Eigen::Vector2d(0, 1), v, {}, 1.0); }).find("sizes"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              integrator.simulate(Eigen::Vector3d(0, std::nan(""), 0), v, {}, 1.0);
            }).find("not finite"),
            std::string::npos);
  EXPECT_NE(error_of([&] { integrator.simulate(q, v, {}, -1.0); }).find("duration"),
            std::string::npos);
  const EventDrivenIntegrator::Input wrong = [](double) { return Eigen::VectorXd::Zero(2); };
  EXPECT_NE(error_of([&] { integrator.simulate(q, v, wrong, 1.0); }).find("input"),
            std::string::npos);
}

TEST(EventDrivenApi, MaxEventsIsAStatusNotAnException) {
  const auto ball = bouncing_ball();
  EventDrivenOptions o;
  o.max_events = 3;
  const auto result = EventDrivenIntegrator(ball, o).simulate(Eigen::Vector3d(0, 1, 0),
                                                              Eigen::Vector3d::Zero(), {}, 10.0);
  EXPECT_EQ(result.status, SimulationStatus::kMaxEvents);
  EXPECT_EQ(result.events.size(), 3u);
  EXPECT_NE(result.message.find("max_events"), std::string::npos);
  EXPECT_LT(result.final_time, 10.0);
}

TEST(EventDrivenApi, EventsCsvAndSummary) {
  const auto ball = bouncing_ball();
  const auto result = EventDrivenIntegrator(ball).simulate(Eigen::Vector3d(0, 1, 0),
                                                           Eigen::Vector3d::Zero(), {}, 3.0);
  ASSERT_TRUE(result.succeeded());
  std::ostringstream csv;
  write_events_csv(csv, result.events);
  std::istringstream lines(csv.str());
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "t,contact,kind,from_mode,to_mode,impulse_n,impulse_t");
  std::getline(lines, line);
  // First impact: t = sqrt(2·0.9/g), impulse (1 + e) m v = 1.5 sqrt(2 g 0.9).
  std::istringstream row(line);
  std::string t, contact, kind, from, to, impulse_n;
  std::getline(row, t, ',');
  std::getline(row, contact, ',');
  std::getline(row, kind, ',');
  std::getline(row, from, ',');
  std::getline(row, to, ',');
  std::getline(row, impulse_n, ',');
  EXPECT_NEAR(std::stod(t), std::sqrt(2 * 0.9 / 9.81), 1e-9);
  EXPECT_EQ(contact, "ball-ground");
  EXPECT_EQ(kind, "impact");
  EXPECT_EQ(from, "open");
  EXPECT_EQ(to, "open");
  EXPECT_NEAR(std::stod(impulse_n), 1.5 * std::sqrt(2 * 9.81 * 0.9), 1e-8);
  std::ostringstream summary;
  write_summary(summary, result);
  EXPECT_NE(summary.str().find("status: success"), std::string::npos);
  EXPECT_NE(
      summary.str().find("impact: " + std::to_string(result.summary.count(EventKind::kImpact))),
      std::string::npos);
  EXPECT_NE(summary.str().find("zeno_rest: 1"), std::string::npos);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
