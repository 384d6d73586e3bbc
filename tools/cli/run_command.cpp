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
#include "lib/output/number_text.hpp"
#include "lib/output/run_outputs.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/output_paths.hpp"
#include "tools/cli/progress_line.hpp"
#include "tools/cli/run_request.hpp"
#include "tools/cli/run_summary.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/engines/registry/engine_registry.hpp"

namespace impactbench::cli {

namespace {

class RunCommand : public Command {
 public:
  explicit RunCommand(CLI::App* app) : Command(app) {
    app->add_option("scenario", request_.scenario, "Scenario name (see `impactbench list`)")
        ->required();
    app->add_option("--engine", request_.engine,
                    "Engine: " + engines::join_names(adapters::engine_names()))
        ->required()
        ->check(CLI::IsMember(adapters::engine_names()));
    app->add_option("--dt", request_.dt, "Time step [s] (default: the scenario's)")
        ->check(kPositiveFinite);
    app->add_option("--tol", request_.tolerance,
                    "Tolerance: Moreau-Jean's solver, the event engine's rtol and atol, "
                    "MuJoCo's and Siconos' solver (default: the scenario's)")
        ->check(kPositiveFinite);
    app->add_option("--solver", request_.solver,
                    "Contact solver: Moreau-Jean's friction solver, Bullet's si|mlcp-dantzig, "
                    "ODE's stepper exact|quick, MuJoCo's pgs|cg|newton, Siconos' "
                    "nsgs|lemke|enum|cpg, the event engine's LCP or friction solver (default: "
                    "the engine's)")
        ->check(CLI::Validator(
            [](std::string& name) { return name.empty() ? std::string("needs a name") : ""; },
            "NAME"));
    app->add_option("--duration", request_.duration, "Simulated time [s] (default: the scenario's)")
        ->check(kPositiveFinite);
    app->add_option("--set", request_.sets, "Override a parameter: name=value (repeatable)");
    app->add_option("--option", request_.options,
                    "Engine setting [ENGINE.]key=value (repeatable; e.g. theta=1, "
                    "box2d.velocity_iterations=8; `impactbench describe` lists every engine's "
                    "keys and values in force)");
    app->add_option("--sample-dt", request_.sample_dt,
                    "Simulated time between trajectory rows [s]; 0: every step (default: every "
                    "step while the file holds at most " +
                        output::number_text(kDefaultMaxValues) + " numbers)")
        ->check(kNonNegativeFinite);
    add_settings_set_option(app, request_.settings_set);
    app->add_flag("--progress", progress_,
                  "Show a progress line on stderr from the start (default: after a few seconds, "
                  "and only when stderr is a terminal)");
    app->add_option("--out", out_, "Trajectory CSV to write")->required();
    app->add_option("--events", events_, "Events CSV to write");
  }

  int run() override {
    PreparedRun prepared = prepare_run(request_);
    const scenario::Scenario& s = prepared.scenario;
    engines::RunOptions& options = prepared.options;
    check_output_path(out_, "--out");
    if (events_) {
      check_output_path(*events_, "--events");
      check_distinct_outputs({{"--out", out_}, {"--events", *events_}});
    }
    const adapters::EngineInfo& engine = built_engine(request_.engine);

    // The rows go to the temporary files as the run goes; an exception (a failed run) leaves
    // them uncommitted, and their destructors remove them. Nothing is kept in memory: samples
    // to the CSV, steps counted only.
    output::RunOutputs outputs(out_, events_);
    std::optional<ProgressLine> progress;
    if (progress_ || ProgressLine::stderr_is_terminal())
      progress.emplace(request_.engine + " on " + s.name, options.duration, progress_);
    options.recording = run_recording(request_.engine, options.duration, request_.sample_dt);
    options.recording.sample_sink = [&outputs](const output::Trajectory& names,
                                               const output::TrajectorySample& sample) {
      outputs.write_sample(names, sample);
    };
    if (progress) options.recording.progress = [&progress](double t) { progress->update(t); };
    const engines::RunResult result = engine.run(s, options);
    progress.reset();  // ends the progress line before the summary
    outputs.commit(result.events);
    print_run_summary(s, options, result);
    return 0;
  }

 private:
  RunRequest request_;  ///< everything but the output files and --progress
  std::filesystem::path out_;
  std::optional<std::filesystem::path> events_;
  bool progress_ = false;
};

}  // namespace

std::unique_ptr<Command> add_run_command(CLI::App& app) {
  return std::make_unique<RunCommand>(
      app.add_subcommand("run", "Run a scenario with one engine and write its trajectory"));
}

}  // namespace impactbench::cli
