// compare's reference trajectory is sampled at the finest compared step (issue #23: every
// engine measured correctly). The error columns read the reference at each run's sample times,
// interpolating it linearly; sampled every 0.01 s, as the event engine samples by default, a
// reference under a deceleration a is off by up to a·Δ²/8 = 6.1e-5 m on the sliding block, which
// compare then reported as Moreau–Jean's error.
//
// The sliding block's bound, derived: Moreau–Jean (θ = ½) is exact for a constant deceleration
// a while the block slides; in the step of the stop it sticks at once, having moved h·v_k/2
// instead of v_k²/(2a) for the v_k < a·h it started that step with, off by at most a·h²/8
// (at v_k = a·h/2), which it keeps. The reference, sampled every h, is off by at most a·h²/8
// between samples. So Moreau–Jean's l∞ error is at most a·h²/4, plus the reference's own
// tolerance (rtol = 1e-10 of positions below 1 m).
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/csv_table.hpp"
#include "tools/compare/compare.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

void expect_moreau_within_its_bound(const std::vector<std::string>& engines) {
  const test_support::TemporaryDirectory work("impactbench_reference_sampling");
  const scenario::Scenario s = scenario::load_scenario_by_name("sliding_block");
  compare::CompareOptions options;
  options.engines = engines;
  options.out = work.path();
  const auto report = compare::run_compare(s, options);
  const double a = s.analytic("deceleration"), h = s.dt;
  const double error = compare::named_value(report.row(engine_name::kMoreau).values, "linf_error");
  EXPECT_LE(error, a * h * h / 4 + 1e-10) << "reference: " << report.reference;
  EXPECT_GT(error, 0.0);
}

TEST(CompareReferenceSampling, TheComparedEventRunSamplesAtTheFinestStep) {
  expect_moreau_within_its_bound({engine_name::kMoreau, engine_name::kEvent});
}

TEST(CompareReferenceSampling, AnExtraEventReferenceSamplesAtTheFinestStepToo) {
  expect_moreau_within_its_bound({engine_name::kMoreau});
}

TEST(CompareReferenceSampling, TheEventRowSaysWhyItSamplesSoFinely) {
  const test_support::TemporaryDirectory work("impactbench_reference_sampling");
  compare::CompareOptions options;
  options.engines = {engine_name::kMoreau, engine_name::kEvent};
  options.out = work.path();
  compare::run_compare(scenario::load_scenario_by_name("sliding_block"), options);
  const auto metrics = test_support::read_csv_table(work.path() / "metrics.csv");
  bool found = false;
  for (std::size_t r = 0; r < metrics.rows.size(); ++r)
    if (metrics.at(r, "engine") == engine_name::kEvent) {
      found = true;
      EXPECT_NE(metrics.at(r, "settings").find("output_interval=0.001 (reference sampling)"),
                std::string::npos)
          << metrics.at(r, "settings");
    }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace impactbench
