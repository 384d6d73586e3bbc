#include "tools/adapters/engine_registry.hpp"

#include <stdexcept>

#include "lib/engines/contact_events.hpp"
#include "lib/engines/engine_settings.hpp"
#include "lib/engines/event_driven/event_engine.hpp"
#include "lib/engines/moreau_jean/moreau_engine.hpp"
#include "tools/adapters/box2d_engine.hpp"
#include "tools/adapters/bullet_engine.hpp"
#include "tools/adapters/scene_from_scenario.hpp"

namespace impactbench::adapters {
namespace {

using engines::apply_settings;
using engines::setting_int;
using engines::setting_number;

engines::RunResult run_box2d_engine(const scenario::Scenario& s, const RunOptions& options) {
  const std::string e = "box2d";
  Box2dSettings b;
  b.impact = engines::impact_criteria_from(e, options.settings);
  apply_settings(e, engines::without_impact_criteria(e, options.settings),
                 {{"velocity_iterations",
                   [&](const std::string& v) {
                     b.velocity_iterations = setting_int(e, "velocity_iterations", v);
                   }},
                  {"position_iterations",
                   [&](const std::string& v) {
                     b.position_iterations = setting_int(e, "position_iterations", v);
                   }},
                  {"restitution_threshold", [&](const std::string& v) {
                     b.restitution_threshold = setting_number(e, "restitution_threshold", v);
                   }}});
  return run_box2d(make_reference_scene(s, options), b);
}

engines::RunResult run_bullet_engine(const scenario::Scenario& s, const RunOptions& options) {
  const std::string e = "bullet";
  BulletSettings b;
  auto number = [&](const char* key, double& field) {
    return [&, key](const std::string& v) { field = setting_number(e, key, v); };
  };
  b.impact = engines::impact_criteria_from(e, options.settings);
  apply_settings(
      e, engines::without_impact_criteria(e, options.settings),
      {{"solver", [&](const std::string& v) { b.solver = parse_bullet_solver(v); }},
       {"solver_iterations",
        [&](const std::string& v) {
          b.solver_iterations = setting_int(e, "solver_iterations", v);
        }},
       {"restitution_threshold", number("restitution_threshold", b.restitution_threshold)},
       {"split_impulse",
        [&](const std::string& v) { b.split_impulse = setting_int(e, "split_impulse", v) != 0; }},
       {"split_impulse_depth", number("split_impulse_depth", b.split_impulse_depth)},
       {"erp", number("erp", b.erp)},
       {"collision_margin", number("collision_margin", b.collision_margin)},
       {"contact_breaking_threshold",
        number("contact_breaking_threshold", b.contact_breaking_threshold)}});
  return run_bullet(make_reference_scene(s, options), b);
}

}  // namespace

const std::vector<EngineInfo>& engine_registry() {
  static const std::vector<EngineInfo> registry = {
      {"moreau", "Moreau-Jean time-stepping (event-capturing), one contact problem per step",
       engines::moreau_jean::run_moreau_jean},
      {"event", "event-driven hybrid integration (event-tracking) with located guards",
       engines::event_driven::run_event_driven},
      {"box2d", "Box2D 2.4.1, sequential impulses (planar scenarios only)", run_box2d_engine},
      {"bullet", "Bullet 3.24 double, sequential impulses or MLCP (planar ones held in the plane)",
       run_bullet_engine},
  };
  return registry;
}

const EngineInfo* find_engine(const std::string& name) {
  for (const EngineInfo& info : engine_registry())
    if (info.name == name) return &info;
  return nullptr;
}

engines::RunResult run_engine(const std::string& engine, const scenario::Scenario& scenario,
                              const RunOptions& options) {
  const EngineInfo* info = find_engine(engine);
  if (!info) {
    std::string names;
    for (const EngineInfo& known : engine_registry()) names += " " + known.name;
    throw std::invalid_argument("unknown engine '" + engine + "' (known:" + names + ")");
  }
  if (!info->run) throw std::invalid_argument("engine '" + engine + "' is not available yet");
  if (!scenario.supports_engine(engine))
    throw std::invalid_argument("scenario '" + scenario.name + "' cannot be run by engine '" +
                                engine + "' (it lists the engines it supports)");
  return info->run(scenario, options);
}

}  // namespace impactbench::adapters
