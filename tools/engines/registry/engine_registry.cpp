#include "tools/engines/registry/engine_registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "lib/output/number_text.hpp"
#include "tools/engines/box2d/box2d_engine.hpp"
#include "tools/engines/bullet/bullet_engine.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/event/event_engine.hpp"
#include "tools/engines/event/event_settings.hpp"
#include "tools/engines/fixed_step/scene_from_scenario.hpp"
#include "tools/engines/moreau/moreau_engine.hpp"
#include "tools/engines/moreau/moreau_settings.hpp"
#include "tools/engines/mujoco/mujoco_engine.hpp"
#include "tools/engines/ode/ode_engine.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/siconos/siconos_settings.hpp"
#ifdef IMPACTBENCH_HAVE_SICONOS_ENGINE
#include "tools/engines/siconos/siconos_engine.hpp"
#include "tools/engines/siconos/siconos_system_engine.hpp"
#endif

namespace impactbench::adapters {
namespace {

// The settings in force first, then what the engine reports as compiled in.
engines::RunResult with_settings(engines::RunResult result, const RunOptions& options) {
  result.settings.insert(result.settings.begin(), options.settings.begin(), options.settings.end());
  return result;
}

// One of our engines behind the registry: run with the options struct its schema parsed when
// the settings were resolved, the settings in force prepended.
template <typename O>
EngineFunction typed_engine(engines::RunResult (*run)(const scenario::Scenario&, const O&,
                                                      const RunOptions&)) {
  return [run](const scenario::Scenario& s, const RunOptions& options) {
    return with_settings(run(s, engines::engine_options_of<O>(options), options), options);
  };
}

// A reference engine behind the registry: the scene built with the step in force (`dt` of its
// options struct, parsed when the settings were resolved), the engine run and the settings
// prepended.
template <typename S>
EngineFunction reference_engine(double S::*dt,
                                engines::RunResult (*run)(const ReferenceScene&, const S&,
                                                          const engines::RecordingOptions&)) {
  return [dt, run](const scenario::Scenario& s, const RunOptions& options) {
    const S& settings = engines::engine_options_of<S>(options);
    return with_settings(
        run(make_reference_scene(s, options.duration, settings.*dt), settings, options.recording),
        options);
  };
}

// The registry as the scenario loader's catalog: a [settings.ENGINE] entry is checked as the
// engine's settings would read it, a step key must not exceed the scenario's duration nor need
// more than kMaxSteps steps, and the scenario's dt and tolerance must be values each engine
// takes for its step and tolerance.
class RegistryCatalog : public scenario::EngineCatalog {
 public:
  const std::vector<std::string>& engine_names() const override { return adapters::engine_names(); }
  std::string setting_problem(const std::string& engine, const std::string& key,
                              const std::string& value, double duration) const override {
    const engines::EngineSettings& info = *find_engine(engine)->settings;
    try {
      const auto in_force =
          info.resolve({{key, value, engines::SettingSource::kScenario}}).in_force;
      const bool is_step =
          std::find(info.dt_keys.begin(), info.dt_keys.end(), key) != info.dt_keys.end();
      if (is_step)
        return engines::step_problem(engine, engines::setting_number(in_force, key), duration);
    } catch (const engines::SettingError& error) {
      return error.detail();
    }
    return "";
  }
  std::string run_value_problem(const std::string& engine, const std::string& field, double value,
                                double duration) const override {
    const engines::EngineSettings& info = *find_engine(engine)->settings;
    for (const std::string& key : field == "dt" ? info.dt_keys : info.tolerance_keys)
      if (std::string problem = setting_problem(engine, key, output::number_text(value), duration);
          !problem.empty())
        return problem;
    return "";
  }
};

// Siconos: planar disks and boxes through the reference scene, the plank–box as our own
// Lagrangian system (siconos_system_engine.hpp); none when Siconos was not found at build time.
EngineFunction siconos_engine() {
#ifdef IMPACTBENCH_HAVE_SICONOS_ENGINE
  return [](const scenario::Scenario& s, const RunOptions& options) {
    const SiconosSettings& settings = engines::engine_options_of<SiconosSettings>(options);
    if (!siconos_states_as_system(s, settings))
      return with_settings(run_siconos(make_reference_scene(s, options.duration, settings.dt),
                                       settings, options.recording),
                           options);
    return with_settings(run_siconos_system(s, settings, options.duration, options.recording),
                         options);
  };
#else
  return {};
#endif
}

}  // namespace

const std::vector<EngineInfo>& engine_registry() {
  static const std::vector<EngineInfo> registry = {
      {engine_name::kMoreau,
       "Moreau-Jean time-stepping (event-capturing), one contact problem per step",
       &engines::moreau_jean::moreau_settings(),
       typed_engine(engines::moreau_jean::run_moreau_jean),
       // 10 Gauss-Seidel sweeps per step; no tolerance to reach (a step that ends above it is
       // counted and the run goes on); no restart from zero, which would double the sweeps.
       {{"solver", "nsgs"},
        {"max_iterations", "10"},
        {"on_failure", "warn"},
        {"cold_restart", "false"}},
       true},
      {engine_name::kEvent,
       "event-driven hybrid integration (event-tracking) with located guards",
       &engines::event_driven::event_settings(),
       typed_engine(engines::event_driven::run_event_driven),
       {}},
      {engine_name::kBox2d,
       "Box2D 2.4.1, sequential impulses (planar scenarios only)",
       &engines::box2d_settings(),
       reference_engine(&Box2dSettings::dt, run_box2d),
       {{"velocity_iterations", "8"}, {"position_iterations", "3"}},  // its defaults
       true,
       "its position correction moves overlapping bodies apart with no force doing work"},
      {engine_name::kBullet,
       "Bullet 3.24 double, sequential impulses or MLCP (planar ones held in the plane)",
       &engines::bullet_settings(),
       reference_engine(&BulletSettings::dt, run_bullet),
       {{"solver_iterations", "10"}},  // its default
       true,
       "its error reduction (split impulse) pushes overlapping bodies apart"},
      {engine_name::kOde,
       "ODE 0.16 double, exact LCP step or quick step (planar ones held in the plane)",
       &engines::ode_settings(),
       reference_engine(&OdeSettings::dt, run_ode),
       {},
       true,
       "its contacts are soft (ERP and CFM: a spring and damper on the penetration)"},
      {engine_name::kMujoco,
       "MuJoCo 2.2.2, soft contacts (solref/solimp), PGS/CG/Newton (planar ones on "
       "slide and hinge joints)",
       &engines::mujoco_settings(),
       reference_engine(&MujocoSettings::timestep, run_mujoco),
       // 10 projected Gauss-Seidel sweeps per step, the unit of the others' iterations.
       {{"solver", "pgs"}, {"iterations", "10"}},
       true,
       "its contacts are soft (solref and solimp: a spring and damper on the penetration)"},
      {engine_name::kSiconos,
       "Siconos 4.4 kernel, MoreauJeanOSI with fc2d/fc3d solvers on our own models, or "
       "EventDriven with Lsodar (one planar body or one sphere against half-spaces, the "
       "plank-box; optional at build time)",
       &engines::siconos_settings(),
       siconos_engine(),
       {}},
  };
  return registry;
}

const std::vector<std::string>& engine_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const EngineInfo& info : engine_registry()) out.push_back(info.name);
    return out;
  }();
  return names;
}

const scenario::EngineCatalog& engine_catalog() {
  static const RegistryCatalog catalog;
  return catalog;
}

std::string not_built_message(const std::string& engine) {
  return "engine '" + engine + "' is not built into this impactbench (its library was not found " +
         "when impactbench was built; see docs/reference-engines.md)";
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
  if (!info->run) throw std::invalid_argument(not_built_message(engine));
  if (!scenario.supports_engine(engine))
    throw std::invalid_argument("scenario '" + scenario.name + "' cannot be run by engine '" +
                                engine + "' (it lists the engines it supports)");
  if (options.recording.timing_only && !info->timing_only_runs)
    throw std::invalid_argument(engine +
                                ": no timing-only run (the fixed-step engines and Moreau-Jean "
                                "have one)");
  return info->run(scenario, options);
}

}  // namespace impactbench::adapters
