// The Zeno rule as a pure function: when it rests a contact, and the accumulation time it
// predicts, against the geometric series of the remaining flights summed term by term.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/zeno_rule.hpp"

namespace impactbench::engines::event_driven {
namespace {

ZenoCandidate bounce(double interval, int impacts_before, double velocity_after, double e) {
  ZenoCandidate c;
  c.t = 2.0;
  c.predicted_interval = interval;
  c.impacts_before = impacts_before;
  c.normal_velocity_after = velocity_after;
  c.restitution = e;
  return c;
}

TEST(EventZenoRule, AShortPredictedFlightRestsAtOnce) {
  const EventDrivenOptions o;  // zeno_min_interval 1e-4
  const ZenoDecision d = decide_zeno(bounce(0.5 * o.zeno_min_interval, 0, 1.0, 0.5), o);
  EXPECT_TRUE(d.rest);
  // Flights Δ, eΔ, e²Δ, ... after t: t + Δ/(1 − e) = 2 + 5e-5/0.5.
  EXPECT_DOUBLE_EQ(d.accumulation_time, 2.0 + 1e-4);
}

TEST(EventZenoRule, ALongFlightBouncesOn) {
  const EventDrivenOptions o;
  const ZenoDecision d = decide_zeno(bounce(2.0 * o.zeno_min_interval, 0, 1.0, 0.5), o);
  EXPECT_FALSE(d.rest);
  EXPECT_EQ(d.accumulation_time, 0.0);
}

TEST(EventZenoRule, ManySlowImpactsInARowRest) {
  const EventDrivenOptions o;  // zeno_impact_count 5, zeno_velocity 1e-2
  const double slow = 0.5 * o.zeno_velocity;
  // The 5th impact in a row (4 before it) with ζ_n⁺ below zeno_velocity rests ...
  EXPECT_TRUE(decide_zeno(bounce(1.0, o.zeno_impact_count - 1, slow, 0.5), o).rest);
  // ... the 4th does not, nor a 5th that leaves fast.
  EXPECT_FALSE(decide_zeno(bounce(1.0, o.zeno_impact_count - 2, slow, 0.5), o).rest);
  EXPECT_FALSE(
      decide_zeno(bounce(1.0, o.zeno_impact_count - 1, 2.0 * o.zeno_velocity, 0.5), o).rest);
}

TEST(EventZenoRule, AccumulationTimeIsTheSumOfTheRemainingFlights) {
  EventDrivenOptions o;
  o.zeno_min_interval = 1.0;  // rest whatever the interval below
  const double e = 0.8, flight = 0.05;
  const ZenoDecision d = decide_zeno(bounce(flight, 0, 1.0, e), o);
  ASSERT_TRUE(d.rest);
  double t = 2.0, next = flight;
  for (int k = 0; k < 400; ++k, next *= e) t += next;  // e^400 < 1e-38: the tail is negligible
  EXPECT_NEAR(d.accumulation_time, t, 1e-14 * t);
}

TEST(EventZenoRule, NoSeriesWithoutRestitutionBelowOneOrANextImpact) {
  EventDrivenOptions o;
  o.zeno_min_interval = 1.0;
  // e = 1: the flights do not shrink; no finite sum, the rest is declared at t.
  EXPECT_DOUBLE_EQ(decide_zeno(bounce(0.05, 0, 1.0, 1.0), o).accumulation_time, 2.0);
  // No next impact predicted (∞): rested by the count rule, at t.
  const double inf = std::numeric_limits<double>::infinity();
  const ZenoDecision d = decide_zeno(bounce(inf, o.zeno_impact_count, 1e-3, 0.5), o);
  EXPECT_TRUE(d.rest);
  EXPECT_DOUBLE_EQ(d.accumulation_time, 2.0);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
