// MuJoCo 2.2.2 on the shipped analytical scenarios, through the registry `impactbench run`
// uses. MuJoCo's contacts are soft (a spring–damper of time scale τ = 5 ms and damping ratio
// ζ(e), mixed by the impedance d = 0.99) and its friction is regularised, so closed forms hold
// only up to that softness. Bounds named MEASURED REGRESSION BOUNDS are not physics: the
// deviation this test printed in a release build (dt = 1e-3) with a margin, with the cause
// stated next to each.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/reference_engine_runs.hpp"
#include "tools/engines/mujoco/mujoco_settings.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

using test_support::named;
using test_support::run_and_measure;

TEST(MujocoEngine, RestitutionDampingRatioInvertsTheOscillatorsRestitution) {
  // e = exp(−ζπ/√(1 − ζ²)) for a linear spring–damper released at zero deflection: the
  // mapping must give back e, and e = 0 the critically damped contact.
  for (const double e : {0.1, 0.5, 0.9, 0.99}) {
    const double zeta = engines::restitution_damping_ratio(e);
    EXPECT_NEAR(std::exp(-zeta * M_PI / std::sqrt(1 - zeta * zeta)), e, 1e-14) << e;
  }
  EXPECT_EQ(engines::restitution_damping_ratio(0.0), 1.0);
}

TEST(MujocoEngine, SettingsAreCheckedAndPrinted) {
  const auto s = scenario::load_scenario_by_name("bouncing_ball");
  engines::SettingsRequest request;
  request.duration = 0.01;
  request.solver = "pgs";
  request.tolerance = 1e-6;
  const engines::RunOptions options = engines::resolve_run_options("mujoco", s, request);
  int shown = 0;
  for (const auto& setting : options.settings) {
    if (setting.key == "solver") shown += setting.value == "pgs";
    if (setting.key == "tolerance") shown += setting.value == "1e-6";
    if (setting.key == "solref_dampratio") shown += setting.value == "restitution";
  }
  EXPECT_EQ(shown, 3);
  test_support::expect_refused_settings("mujoco", "bouncing_ball",
                                        {{"solver", "lemke"},
                                         {"integrator", "rk45"},
                                         {"cone", "round"},
                                         {"impratio", "0"},
                                         {"iterations", "0"},
                                         {"noslip_iterations", "-1"},
                                         {"solref_timeconst", "0.001"},  // below two timesteps
                                         {"solref_dampratio", "0"},
                                         {"solimp_dmin", "1"},
                                         {"solimp_width", "-1"}});
  // d_min above d_max is refused by name.
  request.options = {{"solimp_dmin", "0.9"}, {"solimp_dmax", "0.8"}};
  EXPECT_THROW(engines::resolve_run_options("mujoco", s, request), std::invalid_argument);
}

}  // namespace
}  // namespace impactbench
