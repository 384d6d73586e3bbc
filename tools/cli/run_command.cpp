// `impactbench run SCENARIO --engine NAME [--dt H] [--tol T] [--solver NAME] [--duration T]
//  [--set k=v]... [--option [ENGINE.]key=value]... --out traj.csv [--events ev.csv]`: checks
//  everything it can before asking
// the engine (scenario, overrides, engine support, step and tolerance, output paths), runs it
// and writes the CSVs atomically, so a failed run leaves no file behind.
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "lib/engines/settings/run_settings.hpp"
#include "lib/engines/settings/setting_fields.hpp"
#include "lib/output/run_outputs.hpp"
#include "tools/adapters/engine_registry.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/output_paths.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/run_summary.hpp"
#include "tools/cli/setting_flags.hpp"

namespace impactbench::cli {

namespace {

class RunCommand : public Command {
 public:
  explicit RunCommand(CLI::App* app) : Command(app) {
    app->add_option("scenario", name_, "Scenario name (see `impactbench list`)")->required();
    app->add_option("--engine", engine_,
                    "Engine: " + engines::join_names(scenario::known_engines()))
        ->required()
        ->check(CLI::IsMember(scenario::known_engines()));
    app->add_option("--dt", dt_, "Time step [s] (default: the scenario's)")->check(kPositiveFinite);
    app->add_option("--tol", tolerance_,
                    "Tolerance: Moreau-Jean's solver, the event engine's rtol and atol, "
                    "MuJoCo's and Siconos' solver (default: the scenario's)")
        ->check(kPositiveFinite);
    app->add_option("--solver", solver_,
                    "Contact solver: Moreau-Jean's friction solver, Bullet's si|mlcp-dantzig, "
                    "ODE's stepper exact|quick, MuJoCo's pgs|cg|newton, Siconos' "
                    "nsgs|lemke|enum|cpg, the event engine's LCP or friction solver (default: "
                    "the engine's)")
        ->check(CLI::Validator(
            [](std::string& name) { return name.empty() ? std::string("needs a name") : ""; },
            "NAME"));
    app->add_option("--duration", duration_, "Simulated time [s] (default: the scenario's)")
        ->check(kPositiveFinite);
    app->add_option("--set", sets_, "Override a parameter: name=value (repeatable)");
    app->add_option("--option", options_,
                    "Engine setting [ENGINE.]key=value (repeatable; e.g. theta=1, "
                    "box2d.velocity_iterations=8; `impactbench describe` lists every engine's "
                    "keys and values in force)");
    app->add_option("--out", out_, "Trajectory CSV to write")->required();
    app->add_option("--events", events_, "Events CSV to write");
  }

  int run() override {
    const auto s = scenario::load_scenario_by_name(name_, parse_overrides(sets_), duration_);
    if (!s.supports_engine(engine_))
      throw CliError("scenario '" + s.name + "' cannot be run by engine '" + engine_ +
                         "' (its engines: " + engines::join_names(s.engines, "and") + ")",
                     kExitFailure);
    const engines::RunOptions options = resolve_options(s);
    check_output_path(out_, "--out");
    if (events_) {
      check_output_path(*events_, "--events");
      check_distinct_outputs({{"--out", out_}, {"--events", *events_}});
    }
    const adapters::EngineInfo* engine = adapters::find_engine(engine_);
    if (!engine || !engine->run) throw CliError(adapters::not_built_message(engine_), kExitUsage);

    const engines::RunResult result = engine->run(s, options);
    output::write_run_outputs(result.trajectory, result.events, out_, events_);
    print_run_summary(s, options, result);
    return 0;
  }

 private:
  // Every setting through the one place (engines::resolve_run_options); whatever it refuses
  // was given on the command line, so it is a usage error.
  engines::RunOptions resolve_options(const scenario::Scenario& s) const {
    engines::SettingsRequest request;
    request.dt = dt_;
    request.tolerance = tolerance_;
    request.solver = solver_;
    request.duration = duration_;
    request.options = options_for(parse_option_entries(options_), engine_, true, {engine_});
    try {
      return engines::resolve_run_options(engine_, s, request);
    } catch (const std::invalid_argument& error) {
      throw CliError(error.what(), kExitUsage);
    }
  }

  std::string name_;
  std::string engine_;
  std::optional<double> dt_;
  std::optional<double> tolerance_;
  std::optional<std::string> solver_;
  std::optional<double> duration_;
  std::vector<std::string> sets_;
  std::vector<std::string> options_;
  std::filesystem::path out_;
  std::optional<std::filesystem::path> events_;
};

}  // namespace

std::unique_ptr<Command> add_run_command(CLI::App& app) {
  return std::make_unique<RunCommand>(
      app.add_subcommand("run", "Run a scenario with one engine and write its trajectory"));
}

}  // namespace impactbench::cli
