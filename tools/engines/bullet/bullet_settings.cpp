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
    // The expert set (docs/reference-engines.md#expert-settings). Bullet's wiki page
    // "btContactSolverInfo" (bulletphysics.org/mediawiki-1.5.8): the sequential-impulse (PGS)
    // solver with 4 (low quality) to 20 (good quality) iterations, 10 by default: 20. Bullet's
    // ChangeLog, the entry that added split impulse: it decouples the position
    // correction from the velocity so that correcting a penetration adds no momentum; below
    // m_splitImpulsePenetrationThreshold (-0.04 m) Bullet uses Baumgarte instead, "cheaper"
    // and "more plausible" (not more accurate): split impulse at every depth, 0. ERP 0.2:
    // btContactSolverInfo's default for contacts (m_erp2); the docs give no other value.
    // m_restitutionVelocityThreshold (btContactSolverInfo.h, 0.2 m/s, no documentation): the
    // scenarios' bounces go down to mm/s, so restitution must act there: 1 mm/s.
    s.expert = {{"solver", "si"},
                {"solver_iterations", "20"},
                {"split_impulse", "true"},
                {"split_impulse_depth", "0"},
                {"erp", "0.2"},
                {"restitution_threshold", "0.001"}};
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines
