#pragma once
// Box2D's settings (tools/engines/box2d/box2d_engine.cpp runs them) as plain data with their
// schema, here so that the scenario loader and the command line check them without Box2D itself.
// --dt and the scenario's dt set dt; Box2D has no tolerance and no solver choice.
#include "lib/engines/impact_criteria.hpp"
#include "lib/engines/settings/engine_settings.hpp"

namespace impactbench::engines {

/// The settings that decide Box2D's fidelity; the defaults give its best accuracy on the
/// shipped scenarios (more iterations than Box2D's 8/3, restitution down to 1 mm/s).
struct Box2dSettings {
  double dt = 1e-3;                     ///< fixed step [s] (the scenario's unless given)
  int velocity_iterations = 50;         ///< sequential-impulse sweeps per step (Box2D default 8)
  int position_iterations = 20;         ///< position-correction sweeps (Box2D default 3)
  double restitution_threshold = 1e-3;  ///< [m/s] below which bounces are inelastic (default 1)
  ImpactCriteria impact;                ///< when a closing contact is reported as an impact event
};

const SettingsSchema<Box2dSettings>& box2d_settings_schema();
const EngineSettings& box2d_settings();

}  // namespace impactbench::engines
