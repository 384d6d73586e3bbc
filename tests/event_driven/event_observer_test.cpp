// The event-driven integrator's observer: it gets exactly the samples a run without one keeps,
// in time order, also when they come in several batches, when the run stops early, and when the
// observer itself throws.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"

namespace impactbench::engines::event_driven {
namespace {

// A ball dropped from 0.9 m above the ground (restitution 0.5).
test_support::PlanarTestWorld bouncing_ball() {
  return test_support::PlanarTestWorld({{"ball", 1.0, 0.1}}, 9.81, 0.0, 0.5);
}

const Eigen::Vector3d kDropped(0.0, 1.0, 0.0);

// Every field of both sample lists equal, bit for bit.
void expect_same_samples(const SampleTable& observed, const SampleTable& kept) {
  ASSERT_EQ(observed.size(), kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    EXPECT_EQ(observed[i].t, kept[i].t);
    EXPECT_EQ(observed[i].q, kept[i].q);
    EXPECT_EQ(observed[i].v, kept[i].v);
    EXPECT_EQ(observed[i].energy, kept[i].energy);
  }
}

struct ObservedRun {
  EventDrivenResult result;
  SampleTable samples;
};

ObservedRun observed_run(const EventDrivenIntegrator& integrator, double duration) {
  ObservedRun run;
  run.samples.set_sizes(kDropped.size(), kDropped.size());
  run.result = integrator.simulate(
      kDropped, Eigen::Vector3d::Zero(), {}, duration,
      [&](const SampleView& s) { run.samples.push_back(s.t, s.q, s.v, s.energy); });
  return run;
}

TEST(EventObserver, GetsEverySampleARunWithoutOneKeepsOverSeveralBatches) {
  const auto ball = bouncing_ball();
  const EventDrivenIntegrator integrator(ball);
  // 10 s at the default 0.01 s interval: more than 1,000 samples, several batches of 256.
  const EventDrivenResult kept = integrator.simulate(kDropped, Eigen::Vector3d::Zero(), {}, 10.0);
  ASSERT_TRUE(kept.succeeded());
  ASSERT_GT(kept.samples.size(), 3u * 256u);
  const ObservedRun observed = observed_run(integrator, 10.0);
  ASSERT_TRUE(observed.result.succeeded());
  EXPECT_TRUE(observed.result.samples.empty());
  expect_same_samples(observed.samples, kept.samples);
  for (std::size_t i = 1; i < observed.samples.size(); ++i)
    EXPECT_LE(observed.samples[i - 1].t, observed.samples[i].t) << "sample " << i;
}

TEST(EventObserver, GetsTheSamplesUpToARunThatStopsEarly) {
  const auto ball = bouncing_ball();
  EventDrivenOptions options;
  options.max_events = 3;  // a status, after about 1.6 s: fewer samples than one batch
  const EventDrivenIntegrator integrator(ball, options);
  const EventDrivenResult kept = integrator.simulate(kDropped, Eigen::Vector3d::Zero(), {}, 10.0);
  ASSERT_EQ(kept.status, SimulationStatus::kMaxEvents);
  ASSERT_GT(kept.samples.size(), 10u);
  const ObservedRun observed = observed_run(integrator, 10.0);
  EXPECT_EQ(observed.result.status, SimulationStatus::kMaxEvents);
  expect_same_samples(observed.samples, kept.samples);
}

TEST(EventObserver, AnObserverThatThrowsStopsTheRunWithItsErrorAndIsNotCalledAgain) {
  const auto ball = bouncing_ball();
  const EventDrivenIntegrator integrator(ball);
  int calls = 0;
  const auto failing = [&](const SampleView&) {
    if (++calls == 300) throw std::runtime_error("observer full");
  };
  try {
    integrator.simulate(kDropped, Eigen::Vector3d::Zero(), {}, 10.0, failing);
    FAIL() << "the observer's error did not stop the run";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()), "observer full");
  }
  EXPECT_EQ(calls, 300);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
