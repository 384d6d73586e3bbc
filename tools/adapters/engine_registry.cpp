#include "tools/adapters/engine_registry.hpp"

#include <sstream>
#include <stdexcept>

#include "tools/adapters/box2d_engine.hpp"
#include "tools/adapters/bullet_engine.hpp"
#include "tools/adapters/scene_from_scenario.hpp"

namespace impactbench::adapters {
namespace {

// Applies key=value settings through a table of setters; unknown keys list the valid ones.
template <typename Settings>
using Setter = std::function<void(Settings&, const std::string&)>;

template <typename Settings>
Settings apply_settings(const std::string& engine, const std::map<std::string, std::string>& given,
                        const std::map<std::string, Setter<Settings>>& setters) {
  Settings settings;
  for (const auto& [key, value] : given) {
    const auto it = setters.find(key);
    if (it == setters.end()) {
      std::ostringstream valid;
      for (const auto& [name, unused] : setters) valid << " " << name;
      throw std::invalid_argument(engine + ": unknown setting '" + key + "' (valid:" + valid.str() +
                                  ")");
    }
    it->second(settings, value);
  }
  return settings;
}

int setting_int(const std::string& engine, const std::string& key, const std::string& value) {
  const double x = setting_number(engine, key, value);
  if (x != static_cast<int>(x))
    throw std::invalid_argument(engine + ": setting '" + key + "' must be a whole number");
  return static_cast<int>(x);
}

engines::RunResult run_box2d_engine(const scenario::Scenario& s, const RunOptions& options) {
  const std::string e = "box2d";
  const auto settings = apply_settings<Box2dSettings>(
      e, options.settings,
      {{"velocity_iterations",
        [&](Box2dSettings& b, const std::string& v) {
          b.velocity_iterations = setting_int(e, "velocity_iterations", v);
        }},
       {"position_iterations",
        [&](Box2dSettings& b, const std::string& v) {
          b.position_iterations = setting_int(e, "position_iterations", v);
        }},
       {"restitution_threshold", [&](Box2dSettings& b, const std::string& v) {
          b.restitution_threshold = setting_number(e, "restitution_threshold", v);
        }}});
  return run_box2d(make_reference_scene(s, options), settings);
}

engines::RunResult run_bullet_engine(const scenario::Scenario& s, const RunOptions& options) {
  const std::string e = "bullet";
  const auto settings = apply_settings<BulletSettings>(
      e, options.settings,
      {{"solver",
        [](BulletSettings& b, const std::string& v) { b.solver = parse_bullet_solver(v); }},
       {"solver_iterations",
        [&](BulletSettings& b, const std::string& v) {
          b.solver_iterations = setting_int(e, "solver_iterations", v);
        }},
       {"restitution_threshold",
        [&](BulletSettings& b, const std::string& v) {
          b.restitution_threshold = setting_number(e, "restitution_threshold", v);
        }},
       {"split_impulse",
        [&](BulletSettings& b, const std::string& v) {
          b.split_impulse = setting_int(e, "split_impulse", v) != 0;
        }},
       {"split_impulse_depth",
        [&](BulletSettings& b, const std::string& v) {
          b.split_impulse_depth = setting_number(e, "split_impulse_depth", v);
        }},
       {"erp",
        [&](BulletSettings& b, const std::string& v) { b.erp = setting_number(e, "erp", v); }},
       {"collision_margin",
        [&](BulletSettings& b, const std::string& v) {
          b.collision_margin = setting_number(e, "collision_margin", v);
        }},
       {"contact_breaking_threshold", [&](BulletSettings& b, const std::string& v) {
          b.contact_breaking_threshold = setting_number(e, "contact_breaking_threshold", v);
        }}});
  return run_bullet(make_reference_scene(s, options), settings);
}

}  // namespace

double setting_number(const std::string& engine, const std::string& key, const std::string& value) {
  std::size_t used = 0;
  double x = 0.0;
  try {
    x = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || value.empty())
    throw std::invalid_argument(engine + ": setting '" + key + "' is not a number: '" + value +
                                "'");
  return x;
}

const std::vector<EngineInfo>& engine_registry() {
  static const std::vector<EngineInfo> registry = {
      {"moreau", "Moreau-Jean time-stepping (event-capturing), one contact problem per step", {}},
      {"event", "event-driven hybrid integration (event-tracking) with located guards", {}},
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
