// The energy columns of an engine whose contacts hold energy (issue #23, item 6): on the
// bouncing ball MuJoCo's soft contact takes the ball's 9.8 J while it is compressed and gives it
// back, which energy_max_rise, counting the bodies' kinetic + potential energy only, reports as
// a rise of about 1.5 J. Its row's note says that this is not a gain; Moreau–Jean's row, whose
// contacts are hard, has no such note.
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tools/compare/analytic_errors.hpp"
#include "tools/compare/compare.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

TEST(CompareEnergyNote, ARiseOfAnEngineWhoseContactsHoldEnergyIsNotCalledAGain) {
  const test_support::TemporaryDirectory work("impactbench_energy_note");
  compare::CompareOptions options;
  options.engines = {engine_name::kMoreau, engine_name::kMujoco};
  options.out = work.path();
  const auto report =
      compare::run_compare(scenario::load_scenario_by_name("bouncing_ball"), options);
  const std::string says = "count the bodies' kinetic + potential energy only";

  const auto& mujoco = report.row(engine_name::kMujoco);
  EXPECT_GT(compare::named_value(mujoco.values, "energy_max_rise"), 1.0);
  EXPECT_NE(mujoco.note.find(says + ": its contacts are soft"), std::string::npos) << mujoco.note;
  EXPECT_NE(mujoco.note.find("not a gain of the scheme"), std::string::npos) << mujoco.note;

  const auto& moreau = report.row(engine_name::kMoreau);
  EXPECT_EQ(moreau.note.find(says), std::string::npos) << moreau.note;
}

}  // namespace
}  // namespace impactbench
