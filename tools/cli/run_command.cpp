// `impactbench run SCENARIO --engine NAME [--dt H] [--tol T] [--solver NAME] [--duration T]
//  [--set k=v]... --out traj.csv [--events ev.csv]`: checks everything it can before asking
// the engine (scenario, overrides, engine support, step and tolerance, output paths), runs it
// and writes the CSVs atomically, so a failed run leaves no file behind.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "lib/output/run_outputs.hpp"
#include "tools/adapters/engine_registry.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/output_paths.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/run_summary.hpp"

namespace impactbench::cli {

namespace {

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

// CLI11's PositiveNumber prints the whole double range in its message; this says it plainly.
const CLI::Validator kPositiveFinite(
    [](std::string& text) {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !std::isfinite(value) || !(value > 0.0))
        return "must be a finite number > 0, got '" + text + "'";
      return std::string();
    },
    "POSITIVE");

class RunCommand : public Command {
 public:
  explicit RunCommand(CLI::App* app) : Command(app) {
    app->add_option("scenario", name_, "Scenario name (see `impactbench list`)")->required();
    app->add_option("--engine", engine_, "Engine: " + join(scenario::known_engines()))
        ->required()
        ->check(CLI::IsMember(scenario::known_engines()));
    app->add_option("--dt", dt_, "Time step [s] (default: the scenario's)")->check(kPositiveFinite);
    app->add_option("--tol", tolerance_, "Event/integration tolerance (default: the scenario's)")
        ->check(kPositiveFinite);
    app->add_option("--solver", solver_, "One-step contact solver (default: the engine's)")
        ->check(CLI::Validator(
            [](std::string& name) { return name.empty() ? std::string("needs a name") : ""; },
            "NAME"));
    app->add_option("--duration", duration_, "Simulated time [s] (default: the scenario's)")
        ->check(kPositiveFinite);
    app->add_option("--set", sets_, "Override a parameter: name=value (repeatable)");
    app->add_option("--option", options_,
                    "Engine setting key=value (repeatable; e.g. box2d velocity_iterations=8, "
                    "bullet solver=mlcp-dantzig; `impactbench describe` lists none, the engine "
                    "names the valid keys when one is wrong)");
    app->add_option("--out", out_, "Trajectory CSV to write")->required();
    app->add_option("--events", events_, "Events CSV to write");
  }

  int run() override {
    const auto s = scenario::load_scenario_by_name(name_, parse_overrides(sets_), duration_);
    if (!s.supports_engine(engine_))
      throw CliError("scenario '" + s.name + "' cannot be run by engine '" + engine_ +
                         "' (its engines: " + join(s.engines) + ")",
                     kExitFailure);
    const engines::RunOptions options = resolve_options(s);
    check_output_path(out_, "--out");
    if (events_) {
      check_output_path(*events_, "--events");
      check_distinct_outputs({{"--out", out_}, {"--events", *events_}});
    }
    const adapters::EngineInfo* engine = adapters::find_engine(engine_);
    if (!engine || !engine->run)
      throw CliError("engine '" + engine_ + "' is not available yet", kExitUsage);

    const engines::RunResult result = engine->run(s, options);
    output::write_run_outputs(result.trajectory, result.events, out_, events_);
    print_run_summary(s, result);
    return 0;
  }

 private:
  engines::RunOptions resolve_options(const scenario::Scenario& s) const {
    engines::RunOptions options;
    options.engine = engine_;
    options.dt = dt_.value_or(s.dt);
    options.tolerance = tolerance_.value_or(s.tolerance);
    options.duration = duration_.value_or(s.duration);
    options.solver = solver_;
    for (const std::string& assignment : options_) {
      const auto equals = assignment.find('=');
      if (equals == std::string::npos || equals == 0)
        throw CliError("--option '" + assignment + "' is not key=value", kExitUsage);
      options.settings[assignment.substr(0, equals)] = assignment.substr(equals + 1);
    }
    for (const double value : {options.dt, options.tolerance, options.duration})
      if (!std::isfinite(value))
        throw CliError("--dt, --tol and --duration must be finite", kExitUsage);
    if (options.dt > options.duration)
      throw CliError("--dt " + std::to_string(options.dt) + " exceeds the duration " +
                         std::to_string(options.duration),
                     kExitUsage);
    return options;
  }

  std::string name_;
  std::string engine_;
  std::optional<double> dt_;
  std::optional<double> tolerance_;
  std::string solver_;
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
