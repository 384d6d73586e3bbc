// The event-driven engine on the scenario files: every scenario that lists the engine runs
// through the engine registry as `impactbench run` runs it (the scenario's own defaults), and
// the events and final states match the scenario's analytical quantities (the file's [analytic]
// expressions).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/scenario/scenario.hpp"
#include "tests/support/engines/scenario_runs.hpp"
#include "tests/support/lib/event_complementarity_check.hpp"
#include "tools/engines/event/event_engine.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::engines::event_driven {
namespace {

std::vector<output::EventRecord> of_kind(const RunResult& r, const std::string& kind) {
  std::vector<output::EventRecord> out;
  for (const auto& e : r.events)
    if (e.kind == kind) out.push_back(e);
  return out;
}

RunResult run(const scenario::Scenario& s) {
  return test_support::run_with_scenario_defaults("event", s);
}

// Every scenario that lists the engine runs to its end with time-ordered samples and events,
// and, where nothing drives it (no inputs), its energy never exceeds the initial energy:
// gravity is conservative and impacts (e ≤ 1) and friction only dissipate.
TEST(EventScenarios, EveryScenarioListingTheEngineRunsToTheEndWithoutGainingEnergy) {
  int count = 0;
  for (const auto& name : scenario::list_scenarios()) {
    SCOPED_TRACE(name);
    const auto s = scenario::load_scenario_by_name(name);
    if (!s.supports_engine("event")) continue;
    ++count;
    const RunResult r = run(s);
    const auto& samples = r.trajectory.samples;
    ASSERT_GE(samples.size(), 2u);
    EXPECT_EQ(samples.front().t, 0.0);
    EXPECT_NEAR(samples.back().t, s.duration, 1e-12 * s.duration);
    for (std::size_t i = 1; i < samples.size(); ++i)
      ASSERT_LE(samples[i - 1].t, samples[i].t) << "sample " << i;
    for (std::size_t i = 1; i < r.events.size(); ++i)
      ASSERT_LE(r.events[i - 1].t, r.events[i].t) << "event " << i;
    if (!s.inputs.empty()) continue;
    const double e0 = samples.front().energy;
    double highest = e0;
    for (const auto& sample : samples) highest = std::max(highest, sample.energy);
    std::printf("%s: %zu samples, %zu events, energy rise above E0 %.3g J\n", name.c_str(),
                samples.size(), r.events.size(), highest - e0);
    EXPECT_LE(highest - e0, 1e-8 * std::max(1.0, std::abs(e0)));
  }
  EXPECT_GE(count, 6);
}

// Issue 5: after every event of every scenario the modes satisfy the acceleration-level
// complementarity conditions, checked by an independent KKT solve. The integrator is run
// directly (RunResult does not carry the modes) with the options run_event_driven would use.
// A scenario that cannot meet it is listed with its reason, and the test checks that it still
// fails (so the entry cannot go stale).
const std::map<std::string, std::string> kComplementarityCannot = {
    {"cube_toss",
     "the cube lands flat on four corners at once: the modes chosen after that landing violate "
     "acceleration complementarity by 0.13 (open: the event engine on flat four-corner "
     "landings; validate counts the tosses it fails)"},
};

TEST(EventScenarios, AccelerationComplementarityAfterEveryEvent) {
  for (const auto& name : scenario::list_scenarios()) {
    const auto s = scenario::load_scenario_by_name(name);
    if (!s.supports_engine("event")) continue;
    const BuiltSystem built = build_system(s);
    const EventDrivenIntegrator integrator(*built.system,
                                           options_from(resolve_run_options("event", s)));
    EventDrivenIntegrator::Input input;
    if (!s.inputs.empty()) input = [&s](double t) { return s.input(t); };
    const EventDrivenResult r = integrator.simulate(built.q0, built.v0, input, s.duration);
    ASSERT_TRUE(r.succeeded()) << name << ": " << r.message;
    double worst = 0.0;
    for (const auto& state : r.event_states) {
      const Eigen::VectorXd u =
          input ? input(state.t) : Eigen::VectorXd::Zero(built.system->num_inputs());
      worst = std::max(worst, test_support::acceleration_complementarity_violation(
                                  *built.system, state.q, state.v, u, state.modes));
    }
    std::printf("%s: %zu event states, worst violation %.3g\n", name.c_str(), r.event_states.size(),
                worst);
    if (const auto it = kComplementarityCannot.find(name); it != kComplementarityCannot.end())
      EXPECT_GT(worst, 1e-9) << name << " now meets it: remove its entry (" << it->second << ")";
    else
      EXPECT_LE(worst, 1e-9) << name;
  }
}

TEST(EventScenarios, BouncingBallImpactTimes) {
  const auto s = scenario::load_scenario_by_name("bouncing_ball");
  const auto impacts = of_kind(run(s), "impact");
  ASSERT_GE(impacts.size(), 20u);
  for (std::size_t k = 0; k < impacts.size(); ++k) {
    const double exact = s.analytic("impact_time", static_cast<int>(k));
    EXPECT_NEAR(impacts[k].t, exact, 1e-9 * exact) << "impact " << k;
  }
}

TEST(EventScenarios, InclineSlipTime) {
  // The final speed, and the sliding block's stop, are in the closed-form suite
  // (closed_form_suite_test.cpp).
  const auto s = scenario::load_scenario_by_name("incline");
  const auto r = run(s);
  const auto slips = of_kind(r, "stick_to_slip");
  ASSERT_FALSE(slips.empty());
  EXPECT_NEAR(slips[0].t, s.analytic("slip_time"), 1e-9 * s.analytic("slip_time"));
}

TEST(EventScenarios, RockingBlockHousnerRatio) {
  const auto s = scenario::load_scenario_by_name("rocking_block");
  const auto r = run(s);
  const auto impacts = of_kind(r, "impact");
  ASSERT_GE(impacts.size(), 3u);
  const auto& samples = r.trajectory.samples;
  for (const auto& impact : impacts) {
    // The samples at an event instant: the state before, then after; every impact has them.
    int matches = 0;
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
      if (samples[i].t != impact.t || samples[i + 1].t != impact.t) continue;
      ++matches;
      EXPECT_NEAR(samples[i + 1].v[2] / samples[i].v[2], s.analytic("housner_ratio"), 1e-9)
          << "t = " << impact.t;
      break;
    }
    EXPECT_EQ(matches, 1) << "no before/after samples at the impact t = " << impact.t;
  }
}

TEST(EventScenarios, SphereSpinRollsAtTStar) {
  const auto s = scenario::load_scenario_by_name("sphere_spin");
  const auto r = run(s);
  const auto rolls = of_kind(r, "slip_to_stick");
  ASSERT_EQ(rolls.size(), 1u);
  EXPECT_NEAR(rolls[0].t, s.analytic("t_star"), 1e-9 * s.analytic("t_star"));
  const auto& v = r.trajectory.samples.back().v;
  // The rolling velocity (vx, vy) is in the closed-form suite (closed_form_suite_test.cpp).
  EXPECT_NEAR(v[3], s.analytic("final_wx"), 1e-9);
  EXPECT_NEAR(v[4], s.analytic("final_wy"), 1e-9);
  EXPECT_NEAR(v[5], s.analytic("final_wz"), 1e-9);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
