// `impactbench settings-page` (hidden from --help): docs/settings.md, generated from the
// engines' settings schemas (engine_settings_catalog: keys, what each accepts, defaults, the keys
// the flags set) and the shipped scenarios' own values, so that the page cannot drift from the
// code: tests/cli/cli_settings_page_test.cpp compares the committed page with this output.
// What a key means is not in the schemas; it is here, one line per key, and a key without one
// (or a line without a key) stops the command, so a new setting cannot go undocumented.
#include <algorithm>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/output/number_text.hpp"
#include "lib/scenario/scenario.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tools/cli/command.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {

namespace {

const char* const kRegenerate = "build/tests/bin/impactbench settings-page > docs/settings.md";

/// What each key means, by "engine.key" (units in brackets; ranges and defaults come from the
/// schemas).
const std::map<std::string, std::string>& meanings() {
  static const std::map<std::string, std::string> table = {
      {"moreau.dt", "time step h [s]"},
      {"moreau.theta", "θ of the θ-method"},
      {"moreau.solver", "the one-step friction-contact solver (see [solvers](solvers.md))"},
      {"moreau.tolerance", "the one-step solver's residual tolerance (relative FCLIB measure)"},
      {"moreau.max_iterations",
       "the one-step solver's iteration limit (sweeps, pivots, Newton steps)"},
      {"moreau.on_failure",
       "a step not solved to tolerance: `stop` ends the run at it, `warn` applies the solver's "
       "best iterate, counts a warning and goes on"},
      {"moreau.cold_restart",
       "a warm-started solve that ends unconverged is solved again from zero impulses"},
      {"moreau.forces",
       "`explicit`: forces at q_k + θh v_k, dampers the system differentiates in closed form "
       "θ-implicit; `linearly-implicit`: K and C by central differences (small systems)"},
      {"moreau.contact_margin",
       "[m] candidates: contacts within it at q_k and at the end of the step predicted from the "
       "free motion"},
      {"moreau.cone_facets", "facets of the cone when an LCP solver solves a spatial problem"},
      {"moreau.activation_horizon", "γ of the predicted gap g + γ h ζ_n; `theta`: γ = θ"},
      {"moreau.activation_tolerance",
       "[m] a candidate is active when its predicted gap is at most this"},
      {"event.rtol", "the flow integrator's relative tolerance"},
      {"event.atol",
       "the flow integrator's absolute tolerance, in the units of each state component"},
      {"event.method",
       "the flow integrator: CVODE's `bdf` (Newton, dense Jacobian) or `adams` (fixed-point "
       "corrector, no Jacobian), restarted at order 1 at every event; `erk`: ARKODE's explicit "
       "Runge–Kutta pair `erk_pair` (one-step, keeps its step size across events; non-stiff "
       "flows); `own_erk`: the same pair stepped by our own driver (less work per step; roots "
       "always located on the dense output)"},
      {"event.erk_pair",
       "the pair of `method = erk` and `own_erk`: Dormand–Prince 5(4), Verner 6(5) or Fehlberg "
       "8(7); ignored by CVODE's methods"},
      {"event.startup_order",
       "CVODE's slow step growth after each event holds until its order reaches this, then the "
       "early steps may grow freely (2: a flight under constant forces in a few steps); 0: held "
       "for all early steps, more accurate at loose tolerances; ignored by `erk` and `own_erk`"},
      {"event.dense_output_root_search",
       "locate the guards' roots on the integrator's dense output instead of by its own "
       "rootfinding: fewer guard evaluations; event times agree with the default's to the root "
       "tolerance, not to the bit; always on with `own_erk`"},
      {"event.max_events", "the run stops beyond this many events"},
      {"event.output_interval",
       "[s] between samples; 0: samples at the start, the events and the end only"},
      {"event.max_step", "[s] the flow integrator's largest step; 0: unlimited"},
      {"event.zeno_impact_count",
       "after this many consecutive impacts of one contact, a post-impact normal velocity below "
       "`zeno_velocity` makes the contact persistent"},
      {"event.zeno_velocity", "[m/s] see `zeno_impact_count`"},
      {"event.zeno_min_interval",
       "[s] a predicted time to the contact's next impact below this makes it persistent at once"},
      {"event.contact_margin",
       "[m] pairs tracked with root functions are those within it at each event; another pair is "
       "taken in when its gap falls below half of it"},
      {"event.gap_tolerance", "[m] a gap within this of zero counts as touching at an event"},
      {"event.velocity_tolerance",
       "[m/s] \\|ζ_n\\| below this counts as resting, ‖ζ_t‖ below this as sticking; in space "
       "a slipping contact's friction turns smoothly from its reference direction to "
       "−ζ_t/‖ζ_t‖ as ‖ζ_t‖ grows to it, so that a slip starting from rest can be integrated "
       "([engines](engines.md))"},
      {"event.lcp_solver",
       "solver of the planar contact problems (LCPs); one it works on without solving (a ray, a "
       "stall, the iteration limit) is solved again by enumeration when it has at most 14 "
       "unknowns, counted in the run summary ([engines](engines.md))"},
      {"event.friction_solver", "solver of the spatial contact problems with friction"},
      {"box2d.dt", "fixed step [s]"},
      {"box2d.velocity_iterations", "sequential-impulse sweeps per step (Box2D's own default 8)"},
      {"box2d.position_iterations", "position-correction sweeps per step (Box2D's own default 3)"},
      {"box2d.restitution_threshold",
       "[m/s] slower approaches do not bounce (Box2D's own default 1)"},
      {"bullet.dt", "fixed step [s]"},
      {"bullet.solver",
       "`si`: btSequentialImpulseConstraintSolver (Bullet's default); `mlcp-dantzig`: btMLCPSolver "
       "with btDantzigSolver (a direct LCP per step, slow)"},
      {"bullet.solver_iterations", "solver iterations per step (Bullet's own default 10)"},
      {"bullet.restitution_threshold",
       "[m/s] slower approaches do not bounce (Bullet's own default 0.2)"},
      {"bullet.split_impulse",
       "position correction without adding momentum (Bullet's own default true)"},
      {"bullet.split_impulse_depth",
       "[m] split impulse beyond this penetration (Bullet's own default 0.04)"},
      {"bullet.erp", "contact error reduction (`m_erp2`; Bullet's own default 0.2)"},
      {"bullet.contact_breaking_threshold",
       "[m] `gContactBreakingThreshold` (Bullet's own default 0.02)"},
      {"ode.dt", "fixed step [s]"},
      {"ode.stepper",
       "`exact`: `dWorldStep`, a pivoting LCP; `quick`: `dWorldQuickStep`, Gauss–Seidel sweeps "
       "(ODE has no default: the caller chooses)"},
      {"ode.quick_iterations", "sweeps of the quick step (ODE's own default 20)"},
      {"ode.friction",
       "`pyramid`: `dContactApprox1`, μ·λ_n per direction; `box`: ODE's default, constant "
       "limits μ m g / contact points of the pair"},
      {"ode.erp", "error reduction of contacts and joints (ODE's own default 0.2)"},
      {"ode.cfm", "constraint force mixing (ODE's own default 1e-10 in double)"},
      {"ode.bounce_velocity",
       "[m/s] slower approaches do not bounce (`bounce_vel`; ODE's own: set per contact, no "
       "default)"},
      {"ode.max_contacts", "contact points per pair of geometries"},
      {"mujoco.timestep", "fixed step [s]"},
      {"mujoco.integrator", "MuJoCo's integrator"},
      {"mujoco.solver", "MuJoCo's constraint solver (MuJoCo's own default newton)"},
      {"mujoco.iterations", "the solver's iteration limit (MuJoCo's own default 100)"},
      {"mujoco.tolerance", "the solver's tolerance (MuJoCo's own default 1e-8)"},
      {"mujoco.cone", "friction cone (MuJoCo's own default pyramidal)"},
      {"mujoco.impratio", "friction-to-normal impedance ratio (MuJoCo's own default 1)"},
      {"mujoco.noslip_iterations", "noslip post-solver iterations (MuJoCo's own default 0)"},
      {"mujoco.solref_timeconst",
       "[s] the contact spring's time scale τ, at least two timesteps; `auto`: max(5 ms, 2 "
       "timesteps). With `solref_dampratio` ζ, passed as `solref` in MuJoCo's direct form "
       "(−1/τ², −2ζ/τ); MuJoCo's own `solref` is (0.02, 1)"},
      {"mujoco.solref_dampratio", "damping ratio ζ; `restitution`: ζ = −ln e/√(π² + ln² e)"},
      {"mujoco.solimp_dmin",
       "impedance d at zero penetration, at most `solimp_dmax` (MuJoCo's own 0.9)"},
      {"mujoco.solimp_dmax",
       "impedance d at a penetration of `solimp_width` or more (MuJoCo's own 0.95)"},
      {"mujoco.solimp_width", "[m] (MuJoCo's own default 0.001)"},
      {"siconos.scheme",
       "`moreau_jean`: `MoreauJeanOSI` + `TimeStepping`, fixed steps of `dt`; `event_driven`: "
       "`LsodarOSI` + `EventDriven`, frictionless scenes without force inputs, an event and a "
       "sample every `dt`"},
      {"siconos.dt", "fixed step h [s]"},
      {"siconos.theta", "θ of `MoreauJeanOSI`'s θ-method"},
      {"siconos.gamma",
       "γ of `MoreauJeanOSI`'s activation forecast y_k + γ h ẏ_k (Siconos' own: 0.5, applied "
       "when none is given)"},
      {"siconos.activation_threshold",
       "[m] active when y_k + γ h ẏ_k is at most this (`setConstraintActivationThreshold`; "
       "Siconos' own default 0)"},
      {"siconos.solver",
       "Siconos Numerics' fc2d solvers (`SICONOS_FRICTION_2D_*`); a spatial scene (one sphere) "
       "takes `nsgs` alone, as `SICONOS_FRICTION_3D_NSGS` (others: refused with one line, exit 1)"},
      {"siconos.tolerance", "the solver's tolerance (Siconos' own error measure)"},
      {"siconos.max_iterations", "the solver's iteration limit"},
      {"siconos.rtol",
       "`event_driven`: Lsodar's relative tolerance (scalar, every state component)"},
      {"siconos.atol",
       "`event_driven`: Lsodar's absolute tolerance (scalar, every state component)"},
      {"siconos.event_tolerance",
       "[m] `event_driven`: Siconos' `_TOL_ED`: a contact with \\|gap\\| below it is closed; a gap "
       "below minus it stops the run (Siconos' default 1e4 ε)"},
  };
  return table;
}

/// The two impact-event keys every time-stepper shares (impact_criteria_fields.hpp).
const std::map<std::string, std::string>& shared_meanings() {
  static const std::map<std::string, std::string> table = {
      {"impact_velocity", "[m/s] a closing contact approaching faster is an `impact` event"},
      {"impact_open_time", "[s] a contact open longer than this impacts whatever its speed"},
  };
  return table;
}

std::string meaning(const std::string& engine, const std::string& key) {
  if (const auto it = meanings().find(engine + "." + key); it != meanings().end())
    return it->second;
  if (const auto it = shared_meanings().find(key); it != shared_meanings().end()) return it->second;
  throw std::logic_error("settings page: setting '" + key + "' of " + engine +
                         " has no meaning in tools/cli/settings_page_command.cpp: add one");
}

/// Every line of meanings() names a key of its engine (a removed key takes its line along).
void check_meanings_name_keys() {
  for (const auto& [name, text] : meanings()) {
    const std::string engine = name.substr(0, name.find('.'));
    const engines::EngineSettings* info = engines::find_engine_settings(engine);
    if (!info || !info->has_key(name.substr(engine.size() + 1)))
      throw std::logic_error("settings page: '" + name +
                             "' in tools/cli/settings_page_command.cpp is no setting");
  }
}

std::string code(const std::string& text) {
  return "`" + text + "`";
}

std::string code_list(const std::vector<std::string>& keys) {
  std::vector<std::string> quoted;
  for (const std::string& key : keys) quoted.push_back(code(key));
  return engines::join_names(quoted, "and");
}

/// What --solver NAME sets, by the engine's own solver_key over every solver name.
std::string solver_flag_cell(const engines::EngineSettings& info) {
  if (!info.solver_key) return "refused";
  std::vector<std::string> names;
  for (const auto* registry : {&solvers::lcp_solvers(), &solvers::friction_solvers()})
    for (const auto& solver : *registry)
      if (std::find(names.begin(), names.end(), solver.name) == names.end())
        names.push_back(solver.name);
  std::vector<std::pair<std::string, std::vector<std::string>>> by_key;
  for (const std::string& name : names) {
    const std::string key = info.solver_key(name);
    auto it =
        std::find_if(by_key.begin(), by_key.end(), [&](const auto& e) { return e.first == key; });
    if (it == by_key.end()) it = by_key.insert(by_key.end(), {key, {}});
    it->second.push_back(name);
  }
  if (by_key.size() == 1) return code(by_key.front().first);
  std::string cell;
  for (const auto& [key, solver_names] : by_key)
    cell +=
        (cell.empty() ? "" : "; ") + code(key) + " for " + engines::join_names(solver_names, "and");
  return cell;
}

void write_intro(std::ostream& out) {
  out << "# Engine settings\n\n"
         "<!-- Generated by `impactbench settings-page` from the engines' settings schemas: do "
         "not edit.\n     tests/cli/cli_settings_page_test.cpp fails when this page differs from "
         "the code; regenerate it with\n     "
      << kRegenerate
      << " -->\n\n"
         "Each engine's settings are assembled in one place "
         "(`tools/engines/registry/run_settings.hpp`),\n"
         "in this order of precedence: the engine's default, the scenario file (its `dt` and\n"
         "`tolerance` for the engines that use them, then its `[settings.ENGINE]` table, see\n"
         "[the scenario format](../scenarios/README.md)), the flags `--dt`, `--tol`, "
         "`--solver`, and\n"
         "`--option` entries. A flag or key an engine cannot use is refused (exit 2) with a "
         "message naming\n"
         "the engine and what it accepts, e.g. `box2d: --solver is not a setting of Box2D "
         "(Box2D accepts\n"
         "--dt and --option KEY=VALUE with KEY one of dt, ...)`. Every value is checked before "
         "the run:\n"
         "numbers must be finite and in the key's range, whole numbers whole and in range, "
         "switches `0/1`\n"
         "or `true/false`, names one of the listed ones. With `--settings expert` (`run`, "
         "`compare`,\n"
         "`describe`; the suite runs both sets) a reference engine's expert set, the values its "
         "own\n"
         "documentation gives for accurate rigid contact, comes between its defaults and the "
         "scenario\n"
         "file (source `expert`); our engines have none. Each set with its sources:\n"
         "[reference engines](reference-engines.md#expert-settings).\n\n"
         "`--option` takes `key=value` or `ENGINE.key=value` (repeatable; a key given twice is "
         "an error).\n"
         "In `run` a bare key applies to the engine run and `ENGINE.` must name that engine. In "
         "`compare`\n"
         "the engine must be named (`--option moreau.max_iterations=10 --option\n"
         "box2d.velocity_iterations=8`): a bare key is refused as ambiguous, and so is an engine "
         "that is\n"
         "not compared; `--dt` applies to every compared engine that has a step (refused when "
         "none has).\n\n"
         "The run summary starts with every setting in force and its source, one per line\n"
         "(`setting tolerance 1e-4 (command line)`, sources `default`, `expert`, `scenario`, "
         "`command "
         "line`, and\n"
         "`built in` for what an engine compiles in, e.g. Box2D's linear slop); `compare` writes "
         "the\n"
         "same per engine in the `settings` column of `metrics.csv` (`key=value (source); "
         "...`).\n"
         "`impactbench describe SCENARIO` prints each engine's settings in force. Numbers are "
         "printed\n"
         "as the shortest text that reads back to the same double (`1e-4`, `0.001`).\n\n"
         "The iteration limits are there because a larger value only makes a run that does not "
         "end\n"
         "(`velocity_iterations=1e9` used to hang). `tests/cli/cli_settings_matrix_test.cpp` runs "
         "every key\n"
         "of every engine with a non-default value and checks that it is in force and changes "
         "the run.\n"
         "Why the reference engines' defaults differ from the engines' own, and what they cannot "
         "do:\n"
         "[reference engines](reference-engines.md).\n\n";
}

void write_flags(std::ostream& out) {
  const auto& catalog = engines::engine_settings_catalog();
  out << "## The flags\n\n| flag |";
  for (const auto* info : catalog) out << ' ' << info->engine << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < catalog.size(); ++i) out << "---|";
  out << "\n| `--dt H` |";
  for (const auto* info : catalog)
    out << ' ' << (info->dt_keys.empty() ? "refused (no step)" : code_list(info->dt_keys)) << " |";
  out << "\n| `--tol T` |";
  for (const auto* info : catalog)
    out << ' ' << (info->tolerance_keys.empty() ? "refused" : code_list(info->tolerance_keys))
        << " |";
  out << "\n| `--solver NAME` |";
  for (const auto* info : catalog) out << ' ' << solver_flag_cell(*info) << " |";
  out << "\n\n";
}

void write_engine(std::ostream& out, const engines::EngineSettings& info) {
  const engines::SettingList defaults = info.resolve({}).in_force;
  const auto is_one_of = [](const std::vector<std::string>& keys, const std::string& key) {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
  };
  out << "## " << info.engine << ": " << info.title << "\n\n"
      << "| key | accepts | default | meaning |\n|---|---|---|---|\n";
  for (const engines::SettingKey& key : info.keys) {
    const std::string default_value = is_one_of(info.dt_keys, key.key) ? "the scenario's `dt`"
                                      : is_one_of(info.tolerance_keys, key.key)
                                          ? "the scenario's `tolerance`"
                                          : code(engines::setting_value(defaults, key.key));
    out << "| " << code(key.key) << " | " << key.accepts << " | " << default_value << " | "
        << meaning(info.engine, key.key) << " |\n";
  }
  out << '\n';
}

void write_scenarios(std::ostream& out) {
  out << "## The shipped scenarios' values\n\n"
         "The `dt` and `tolerance` of each file in `scenarios/`, and the values of its "
         "`[settings.ENGINE]`\n"
         "entries, which replace the defaults above for that scenario.\n\n"
         "| scenario | `dt` [s] | `tolerance` | `[settings.ENGINE]` entries |\n|---|---|---|---|\n";
  for (const std::string& name : scenario::list_scenarios()) {
    const scenario::Scenario s = scenario::load_scenario_by_name(name);
    std::string entries;
    for (const auto& [engine, settings] : s.engine_settings) {
      // The value in force, as `describe` prints it (a whole number as written, not as 1e5).
      const engines::SettingList in_force = engines::resolve_run_options(engine, s).settings;
      for (const auto& [key, value] : settings)
        entries += (entries.empty() ? "" : ", ") +
                   code(engine + "." + key + " = " + engines::setting_value(in_force, key));
    }
    out << "| " << name << " | " << output::number_text(s.dt) << " | "
        << output::number_text(s.tolerance) << " | " << (entries.empty() ? "none" : entries)
        << " |\n";
  }
}

class SettingsPageCommand : public Command {
 public:
  using Command::Command;
  int run() override {
    check_meanings_name_keys();
    std::ostringstream page;  // nothing printed unless the whole page was made
    write_intro(page);
    write_flags(page);
    for (const engines::EngineSettings* info : engines::engine_settings_catalog())
      write_engine(page, *info);
    write_scenarios(page);
    std::cout << page.str();
    return 0;
  }
};

}  // namespace

std::unique_ptr<Command> add_settings_page_command(CLI::App& app) {
  // In no group: CLI11 leaves it out of --help (a maintainer's tool, not a user's command).
  CLI::App* command = app.add_subcommand(
      "settings-page", "Print docs/settings.md as generated from the settings schemas");
  command->group("");
  return std::make_unique<SettingsPageCommand>(command);
}

}  // namespace impactbench::cli
