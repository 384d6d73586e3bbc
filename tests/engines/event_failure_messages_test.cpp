// How event-driven runs fail: one line naming where (times as the shortest text that reads back
// to the same double, as every number the project prints) and, for a flow the method cannot
// integrate, what to change, in bounded time.
#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/scenario/scenario.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::engines::event_driven {
namespace {

// The number after "at t = " in a message.
double time_in(const std::string& message) {
  const auto at = message.find("at t = ");
  EXPECT_NE(at, std::string::npos) << message;
  return at == std::string::npos ? -1.0 : std::stod(message.substr(at + 7));
}

TEST(EventFailureMessages, TimesReadBackToTheFailureTime) {
  const test_support::PlanarTestWorld ball({{"ball", 1.0, 0.1}}, 9.81, 0.0, 0.5);
  EventDrivenOptions o;
  o.max_events = 3;
  const auto result = EventDrivenIntegrator(ball, o).simulate(Eigen::Vector3d(0, 1, 0),
                                                              Eigen::Vector3d::Zero(), {}, 10.0);
  ASSERT_EQ(result.status, SimulationStatus::kMaxEvents);
  // The third impact's time: six decimals (%f) would not read back to it.
  EXPECT_EQ(time_in(result.message), result.final_time) << result.message;
}

// The plank–box with a plank of 1e-12 kg: the hinge's spring and damper make the plank's
// motion stiff (b_P/I ≈ 6e12 1/s), Adams' steps collapse, and without a bound on the work the
// run crawls near t = 0 for hours. BDF integrates it.
TEST(EventFailureMessages, AStiffFlowFailsSoonNamingTheSettingToChange) {
  const scenario::Scenario s = scenario::load_scenario_by_name("plank_box", {{"m_P", 1e-12}});
  const BuiltSystem built = build_system(s);
  EventDrivenIntegrator::Input input;
  if (!s.inputs.empty()) input = [&s](double t) { return s.input(t); };
  EventDrivenOptions o;
  o.relative_tolerance = o.absolute_tolerance = s.tolerance;
  const auto start = std::chrono::steady_clock::now();
  const EventDrivenResult adams =
      EventDrivenIntegrator(*built.system, o).simulate(built.q0, built.v0, input, 0.01);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(adams.status, SimulationStatus::kIntegratorFailure);
  EXPECT_LT(adams.final_time, 0.01);
  EXPECT_NE(adams.message.find("--option method=bdf"), std::string::npos) << adams.message;
  EXPECT_EQ(adams.message.find('\n'), std::string::npos) << adams.message;
  EXPECT_LT(seconds, 60.0);  // bounded: the limit is work, not time, but a hang is hours
  o.method = FlowMethod::kBdf;
  const EventDrivenResult bdf =
      EventDrivenIntegrator(*built.system, o).simulate(built.q0, built.v0, input, 0.01);
  EXPECT_TRUE(bdf.succeeded()) << bdf.message;
}

}  // namespace
}  // namespace impactbench::engines::event_driven
