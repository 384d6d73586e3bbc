// Event-driven: on a row of N balls the engine tracks only the pairs that can touch (contact
// margin of the newtons_cradle scenario), and the chain of binary impacts still ends in the
// closed form of the cradle.
#include <cmath>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/engines/event/event_engine.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::engines::event_driven {
namespace {

// Equal masses, e = 1, neighbours `gap` apart, ball 0 moving at v0: each binary impact swaps
// the two velocities, so ball k + 1 is struck at t_k = (k + 1) gap / v0 (k = 0 … N − 2) and
// after the chain the last ball moves at v0 while the others rest. Before impact k ball k has
// closed its gap to k + 1 and rests there: its gap to k + 2 stays 2 radius + gap = 0.21 m, so
// no pair but neighbours ever comes within the scenario's margin (0.05 m): N − 1 tracked pairs.
struct Cradle {
  EventDrivenResult result;
  int nv_per_body = 0;
};

Cradle run_cradle(int count, bool every_pair) {
  const scenario::Scenario s =
      scenario::load_scenario_by_name("newtons_cradle", {{"count", count}});
  EventDrivenOptions options = options_from(resolve_run_options("event", s, {}));
  if (every_pair) options.contact_margin = 1e3;  // the former default: every pair tracked
  const engines::BuiltSystem built = engines::build_system(s);
  Cradle c;
  c.result = EventDrivenIntegrator(*built.system, options).simulate(built.q0, built.v0, {}, 0.2);
  c.nv_per_body = static_cast<int>(built.v0.size()) / count;
  return c;
}

class EventCradleTracking : public ::testing::TestWithParam<int> {};

TEST_P(EventCradleTracking, TracksNeighboursOnlyAndEndsInTheClosedForm) {
  const int n = GetParam();
  const double v0 = 1.0, gap = 0.01;  // the scenario's defaults
  const Cradle c = run_cradle(n, /*every_pair=*/false);
  ASSERT_TRUE(c.result.succeeded()) << c.result.message;
  EXPECT_EQ(c.result.summary.max_tracked_contacts, n - 1);
  ASSERT_EQ(c.result.summary.count(EventKind::kImpact), n - 1);
  int k = 0;
  for (const Event& e : c.result.events) {
    ASSERT_EQ(e.kind, EventKind::kImpact);
    EXPECT_NEAR(e.t, (k + 1) * gap / v0, 1e-9) << "impact " << k;
    ++k;
  }
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(c.result.v(c.nv_per_body * i), i == n - 1 ? v0 : 0.0, 1e-9) << "ball " << i;
}

// The count itself: with a margin beyond the row's length every pair is tracked.
TEST(EventCradleTrackingMargin, AWideMarginTracksEveryPair) {
  const int n = 6;
  const Cradle c = run_cradle(n, /*every_pair=*/true);
  ASSERT_TRUE(c.result.succeeded()) << c.result.message;
  EXPECT_EQ(c.result.summary.max_tracked_contacts, n * (n - 1) / 2);
  EXPECT_NEAR(c.result.v(c.nv_per_body * (n - 1)), 1.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Rows, EventCradleTracking, ::testing::Values(3, 8, 16));

}  // namespace
}  // namespace impactbench::engines::event_driven
