// `impactbench run SCENARIO --engine NAME [--dt H] [--tol T] [--solver NAME] [--duration T]
//  [--set k=v]... [--option [ENGINE.]key=value]... [--sample-dt S] [--progress] --out traj.csv
//  [--events ev.csv]`: checks everything it can before asking the engine (scenario, overrides,
// engine support, step and tolerance, output paths), runs it streaming the sampled states into
// the trajectory CSV (nothing is kept in memory) and commits the CSVs at the end, so a failed
// run leaves no file behind.
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "lib/engines/settings/setting_fields.hpp"
#include "lib/engines/step_count.hpp"
#include "lib/output/number_text.hpp"
#include "lib/output/run_outputs.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/output_paths.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/progress_line.hpp"
#include "tools/cli/run_summary.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {

namespace {

/// The trajectory CSV of `run` holds about at most this many numbers (rows × columns) unless
/// --sample-dt says otherwise (docs/cli.md).
constexpr double kDefaultMaxValues = 1e6;

class RunCommand : public Command {
 public:
  explicit RunCommand(CLI::App* app) : Command(app) {
    app->add_option("scenario", name_, "Scenario name (see `impactbench list`)")->required();
    app->add_option("--engine", engine_, "Engine: " + engines::join_names(adapters::engine_names()))
        ->required()
        ->check(CLI::IsMember(adapters::engine_names()));
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
    app->add_option("--sample-dt", sample_dt_,
                    "Simulated time between trajectory rows [s]; 0: every step (default: every "
                    "step while the file holds at most " +
                        output::number_text(kDefaultMaxValues) + " numbers)")
        ->check(kNonNegativeFinite);
    app->add_flag("--progress", progress_,
                  "Show a progress line on stderr from the start (default: after a few seconds, "
                  "and only when stderr is a terminal)");
    app->add_option("--out", out_, "Trajectory CSV to write")->required();
    app->add_option("--events", events_, "Events CSV to write");
  }

  int run() override {
    const auto s = scenario::load_scenario_by_name(name_, parse_overrides(sets_), duration_);
    if (!s.supports_engine(engine_))
      throw CliError("scenario '" + s.name + "' cannot be run by engine '" + engine_ +
                         "' (its engines: " + engines::join_names(s.engines, "and") + ")",
                     kExitFailure);
    engines::RunOptions options = resolve_options(s);
    check_sample_interval(options.duration);
    check_output_path(out_, "--out");
    if (events_) {
      check_output_path(*events_, "--events");
      check_distinct_outputs({{"--out", out_}, {"--events", *events_}});
    }
    const adapters::EngineInfo* engine = adapters::find_engine(engine_);
    if (!engine || !engine->run) throw CliError(adapters::not_built_message(engine_), kExitUsage);

    // The rows go to the temporary files as the run goes; an exception (a failed run) leaves
    // them uncommitted, and their destructors remove them.
    output::RunOutputs outputs(out_, events_);
    std::optional<ProgressLine> progress;
    if (progress_ || ProgressLine::stderr_is_terminal())
      progress.emplace(engine_ + " on " + s.name, options.duration, progress_);
    options.recording = recording(options.duration, outputs, progress);
    const engines::RunResult result = engine->run(s, options);
    progress.reset();  // ends the progress line before the summary
    outputs.commit(result.events);
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

  // An interval so small that duration / interval leaves the doubles' exact range (a subnormal
  // 5e-324 overflows it) would thin the rows instead of keeping each: refused like a step.
  void check_sample_interval(double duration) const {
    if (!sample_dt_ || *sample_dt_ == 0.0 || !(duration > 0.0)) return;
    try {
      engines::checked_step_count("--sample-dt", duration, *sample_dt_, "sample interval");
    } catch (const std::invalid_argument& error) {
      throw CliError(error.what(), kExitUsage);
    }
  }

  // Nothing kept in memory: samples to the CSV, steps counted only.
  engines::RecordingOptions recording(double duration, output::RunOutputs& outputs,
                                      std::optional<ProgressLine>& progress) const {
    engines::RecordingOptions recording;
    recording.keep_samples = false;
    recording.keep_steps = false;
    recording.sample_interval = sample_dt_.value_or(0.0);
    // The budget thins the steps of a time-stepper; the event engine samples at its own
    // output_interval and at events, which it keeps.
    const engines::EngineSettings* settings = engines::find_engine_settings(engine_);
    if (!sample_dt_ && settings && !settings->dt_keys.empty())
      recording.max_values = kDefaultMaxValues;
    recording.duration = duration;
    recording.sample_sink = [&outputs](const output::Trajectory& names,
                                       const output::TrajectorySample& sample) {
      outputs.write_sample(names, sample);
    };
    if (progress) recording.progress = [&progress](double t) { progress->update(t); };
    return recording;
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
  std::optional<double> sample_dt_;
  bool progress_ = false;
};

}  // namespace

std::unique_ptr<Command> add_run_command(CLI::App& app) {
  return std::make_unique<RunCommand>(
      app.add_subcommand("run", "Run a scenario with one engine and write its trajectory"));
}

}  // namespace impactbench::cli
