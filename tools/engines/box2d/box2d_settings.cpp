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
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines
