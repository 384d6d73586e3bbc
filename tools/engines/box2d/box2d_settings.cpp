#include "tools/engines/box2d/box2d_settings.hpp"

#include <limits>

#include "lib/engines/impact_criteria_fields.hpp"
#include "tools/engines/engine_names.hpp"

namespace impactbench::engines {

const SettingsSchema<Box2dSettings>& box2d_settings_schema() {
  using O = Box2dSettings;
  // 10,000 sweeps per step is far beyond convergence; more only makes a run that never ends.
  // Box2D computes in float: thresholds stay well inside its range.
  static const SettingsSchema<O> schema(
      engine_name::kBox2d, "Box2D",
      with_impact_criteria<O>(
          {number_field("dt", &O::dt, {0.0, std::numeric_limits<double>::infinity(), true}),
           whole_field("velocity_iterations", &O::velocity_iterations, 1, 10000),
           whole_field("position_iterations", &O::position_iterations, 0, 10000),
           number_field("restitution_threshold", &O::restitution_threshold, {0.0, 1000.0})},
          &O::impact));
  return schema;
}

const EngineSettings& box2d_settings() {
  static const EngineSettings settings = [] {
    EngineSettings s = box2d_settings_schema().describe();
    s.dt_keys = {"dt"};
    // The expert set (docs/reference-engines.md#expert-settings). Box2D 2.4.1's manual, "Hello
    // Box2D", "Simulating the World" (docs/hello.md of the v2.4.1 tag): it suggests 8 velocity
    // and 3 position iterations and says that more iterations give a better simulation at a
    // cost, with no count for accuracy; "Dynamics", "Simulation" (docs/dynamics.md) asks for a
    // small fixed step before many iterations (the step here is the scenario's). No count
    // given: the ones this adapter found converged on the scenarios (its defaults, 50 and 20).
    // b2FixtureDef::restitutionThreshold (b2_fixture.h): collisions slower than it do not
    // bounce, 1 m/s by default; the scenarios' bounces go down to mm/s, so restitution must act
    // there: 1 mm/s.
    s.expert = {{"velocity_iterations", "50"},
                {"position_iterations", "20"},
                {"restitution_threshold", "0.001"}};
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines
