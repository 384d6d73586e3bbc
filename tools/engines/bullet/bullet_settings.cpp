#include "tools/engines/bullet/bullet_settings.hpp"

#include <limits>

#include "lib/engines/impact_criteria_fields.hpp"
#include "tools/engines/engine_names.hpp"

namespace impactbench::engines {

const SettingsSchema<BulletSettings>& bullet_settings_schema() {
  using O = BulletSettings;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // The MLCP Lemke solver is not offered: it throws bodies away in Debian's build. The box
  // margin is not a setting: Bullet's box–box and sphere–box algorithms use the exact box, so
  // no scene of ours would show it (the cli_settings_matrix_test measured none).
  static const SettingsSchema<O> schema(
      engine_name::kBullet, "Bullet",
      with_impact_criteria<O>(
          {number_field("dt", &O::dt, {0.0, kInf, true}),
           choice_field<O, BulletSolver>("solver", &O::solver,
                                         {{"si", BulletSolver::kSequentialImpulse},
                                          {"mlcp-dantzig", BulletSolver::kMlcpDantzig}}),
           whole_field("solver_iterations", &O::solver_iterations, 1, 10000),
           number_field("restitution_threshold", &O::restitution_threshold, {0.0, 1000.0}),
           switch_field("split_impulse", &O::split_impulse),
           number_field("split_impulse_depth", &O::split_impulse_depth, {0.0, kInf}),
           number_field("erp", &O::erp, {0.0, 1.0}),
           number_field("contact_breaking_threshold", &O::contact_breaking_threshold,
                        {0.0, kInf, true})},
          &O::impact));
  return schema;
}

const EngineSettings& bullet_settings() {
  static const EngineSettings settings = [] {
    EngineSettings s = bullet_settings_schema().describe();
    s.dt_keys = {"dt"};
    s.solver_key = [](const std::string&) { return std::string("solver"); };
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines
