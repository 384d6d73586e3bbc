// `impactbench validate [--engines a,b,...] [--tosses test|train|all|LIST] [--data DIR]
//  [--initial-state sample|fit] [--parameters default|fitted|FILE] [--set k=v]...
//  [--option ENGINE.key=value]... [--trace-toss T]
//  [--no-plots] --out DIR`: engines against recorded cube tosses (docs/real-tosses.md); CSV
// files, summary.md and PNG plots in DIR, the summary on stdout.
// Usage errors exit 2 and bad toss files exit 1, before anything is run or written.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "lib/resources/resource_paths.hpp"
#include "lib/validation/toss_state.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/output_paths.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/progress_line.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/cli/validation_parameters.hpp"
#include "tools/cli/validation_plots.hpp"
#include "tools/cli/validation_report.hpp"
#include "tools/cli/validation_study.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

class ValidateCommand : public Command {
 public:
  explicit ValidateCommand(CLI::App* app) : Command(app) {
    app->add_option("--engines", engines_,
                    "Comma-separated engines (default: every built engine cube_toss lists)")
        ->delimiter(',');
    app->add_option("--tosses", tosses_,
                    "test (odd toss numbers, default), train (even), all, or numbers and ranges "
                    "like 1,3,10-20");
    app->add_option(
        "--data", data_,
        "Folder of toss CSV files (default: the shipped scenarios/data/cube_toss/tosses)");
    app->add_option("--initial-state", initial_state_,
                    "sample: the first sample's state; fit: a ballistic fit of the samples "
                    "before the first contact")
        ->check(CLI::IsMember({"sample", "fit"}));
    app->add_option("--set", sets_,
                    "Override a cube_toss parameter: name=value (repeatable), e.g. friction=0.2");
    app->add_option("--parameters", parameters_,
                    "default (the scenario's), fitted (each engine's fit on the training split, "
                    "scenarios/data/cube_toss/fitted_parameters.toml) or a file in that format; "
                    "--set and --option apply over it");
    app->add_option("--option", options_,
                    "An engine's setting: ENGINE.key=value (repeatable), e.g. "
                    "mujoco.solref_timeconst=0.01 (impactbench describe cube_toss lists them)");
    app->add_option("--trace-toss", traced_,
                    "The toss whose trajectories toss_trajectory.csv and its plot show "
                    "(a file stem such as toss_017; default: the first selected toss)");
    app->add_option("--out", out_, "Output directory (created if missing)")->required();
    app->add_flag("--no-plots", no_plots_, "Skip the matplotlib plots");
    app->add_flag("--progress", progress_, "Show the progress line from the start");
  }

  int run() override {
    const scenario::ParameterOverrides overrides = parse_overrides(sets_);
    for (const auto& [name, value] : overrides)
      if (validation::is_state_parameter(name))
        throw CliError("--set " + name + ": the initial state comes from each toss", kExitUsage);
    // Loads the scenario with the overrides: an unknown name or a bad value stops here.
    const scenario::Scenario base = scenario::load_scenario_by_name("cube_toss", overrides);
    const std::vector<std::string> engines = checked_engines(base);
    const std::filesystem::path data = data_ ? *data_ : resources::cube_toss_directory();
    ValidationRequest request;
    request.engines = engines;
    request.overrides = overrides;
    const auto entries = parse_option_entries(options_);
    for (const OptionEntry& entry : entries) {
      if (entry.engine.empty())
        throw CliError("validate: --option '" + entry.key +
                           "=...' must name its engine (ENGINE.key=value, e.g. mujoco." +
                           entry.key + "=...)",
                       kExitUsage);
      if (std::find(engines.begin(), engines.end(), entry.engine) == engines.end())
        throw CliError("validate: --option " + entry.engine + "." + entry.key +
                           ": the engine is not validated here (--engines)",
                       kExitUsage);
      request.options[entry.engine].emplace_back(entry.key, entry.value);
    }
    apply_parameter_table(request);
    check_validation_options(base, request.options);
    request.initial_state =
        initial_state_ == "fit" ? InitialStateKind::kFit : InitialStateKind::kSample;
    request.tosses = read_tosses(data, tosses_);
    const validation::Toss& traced = traced_toss(request.tosses);
    request.traced_toss = traced.name;
    // Only now, with every input checked, the output directory.
    std::error_code error;
    std::filesystem::create_directories(out_, error);
    if (error || !std::filesystem::is_directory(out_))
      throw CliError("--out " + out_.string() + ": cannot create the directory", kExitFailure);
    for (const std::string& name : validation_output_names())
      check_output_path(out_ / name, "--out");
    if (!no_plots_)
      for (const std::string& name : validation_plot_names())
        check_output_path(out_ / name, "--out");
    std::optional<ProgressLine> line;
    request.progress = [&](double done, double total) {
      if (!line) line.emplace("validate", total, progress_);
      line->update(done);
    };
    const auto start = std::chrono::steady_clock::now();
    const std::vector<TossRun> runs = run_validation(request);
    line.reset();
    ValidationHeader header;
    header.data = data_ ? data_->string() : "scenarios/data/cube_toss/tosses";
    header.selection = tosses_;
    header.parameter_set = parameters_;
    header.table = table_text_;
    header.initial_state = initial_state_;
    for (const auto& s : sets_) header.overrides += (header.overrides.empty() ? "" : " ") + s;
    for (const auto& o : options_) header.overrides += (header.overrides.empty() ? "" : " ") + o;
    header.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string summary = validation_summary(header, engines, runs);
    write_validation_outputs(out_, summary, engines, runs, traced);
    std::cout << summary << "wrote";
    for (const std::string& name : validation_output_names())
      std::cout << (name == validation_output_names().front() ? " " : ", ")
                << (out_ / name).string();
    if (!no_plots_) {
      plot_validation(resources::python_interpreter(), resources::scripts_directory(), out_);
      for (const std::string& name : validation_plot_names())
        std::cout << ", " << (out_ / name).string();
    }
    std::cout << "\n";
    return 0;
  }

 private:
  std::vector<std::string> checked_engines(const scenario::Scenario& s) const {
    std::vector<std::string> names;
    if (engines_.empty()) return cube_toss_engines(s);
    for (const std::string& name : engines_) {
      const adapters::EngineInfo* info = adapters::find_engine(name);
      if (!info) throw CliError("--engines: unknown engine '" + name + "'", kExitUsage);
      if (!info->run) throw CliError(adapters::not_built_message(name), kExitUsage);
      if (!s.supports_engine(name))
        throw CliError("--engines: cube_toss does not list " + name, kExitUsage);
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    return names;
  }

  /// --parameters: each validated engine's entry of the table, under --set and --option.
  void apply_parameter_table(ValidationRequest& request) {
    if (parameters_ == "default") return;
    table_text_ = cli::apply_parameter_table(request, parameters_ == "fitted"
                                                          ? fitted_parameters_path()
                                                          : std::filesystem::path(parameters_));
  }

  const validation::Toss& traced_toss(const std::vector<validation::Toss>& tosses) const {
    if (traced_.empty()) return tosses.front();
    for (const validation::Toss& toss : tosses)
      if (toss.name == traced_) return toss;
    throw CliError(
        "--trace-toss " + traced_ + ": not among the selected tosses (--tosses " + tosses_ + ")",
        kExitUsage);
  }

  std::vector<std::string> engines_;
  std::string tosses_ = "test";
  std::string traced_;
  std::string parameters_ = "default";
  std::string table_text_;
  bool no_plots_ = false;
  std::optional<std::filesystem::path> data_;
  std::string initial_state_ = "sample";
  std::vector<std::string> sets_;
  std::vector<std::string> options_;
  std::filesystem::path out_;
  bool progress_ = false;
};

}  // namespace

std::unique_ptr<Command> add_validate_command(CLI::App& app) {
  return std::make_unique<ValidateCommand>(app.add_subcommand(
      "validate", "Run engines from recorded cube tosses and score them against the recordings"));
}

}  // namespace impactbench::cli
