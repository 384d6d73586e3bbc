// `impactbench compare SCENARIO [--engines a,b,...] [--dt H] [--duration T] [--set k=v]...
//  [--option ENGINE.key=value]... [--settings default|expert] --out DIR`: every engine on one
//  scenario; metrics.csv, per-engine CSVs and PNG plots in DIR,
// and the metrics table on stdout.
#include <algorithm>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "lib/engines/settings/setting_fields.hpp"
#include "lib/resources/resource_paths.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/compare_request.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/compare/compare.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

class CompareCommand : public Command {
 public:
  explicit CompareCommand(CLI::App* app) : Command(app) {
    app->add_option("scenario", name_, "Scenario name (see `impactbench list`)")->required();
    app->add_option("--engines", engines_,
                    "Comma-separated engines (default: every available one the scenario lists)")
        ->delimiter(',');
    app->add_option("--dt", dt_, "Time step of the time-stepping engines [s] (default: scenario's)")
        ->check(kPositiveFinite);
    app->add_option("--duration", duration_, "Simulated time [s] (default: scenario's)")
        ->check(kPositiveFinite);
    app->add_option("--set", sets_, "Override a parameter: name=value (repeatable)");
    app->add_option("--option", options_,
                    "Engine setting ENGINE.key=value (repeatable; the engine must be named: "
                    "e.g. moreau.max_iterations=10, box2d.velocity_iterations=8)");
    add_settings_set_option(app, settings_set_);
    app->add_option("--out", out_, "Output directory (created if missing)")->required();
    app->add_flag("--no-plots", no_plots_, "Skip the matplotlib plots");
  }

  int run() override {
    const auto s = scenario::load_scenario_by_name(name_, parse_overrides(sets_));
    compare::CompareOptions options =
        compare_options(s, CompareRequest{engines_, dt_, duration_, options_, out_, settings_set_});
    if (!no_plots_) {
      options.python = resources::python_interpreter();
      options.tools_dir = resources::scripts_directory();
    }
    const auto report = compare::run_compare(s, options);
    std::cout << s.name << "\n" << compare::format_report(report);
    std::cout << "wrote " << (out_ / "metrics.csv").string();
    for (const auto& png : report.plots) std::cout << ", " << png;
    std::cout << "\n";
    if (report.any_failed()) {
      std::vector<std::string> failed;
      for (const auto& row : report.rows)
        if (!row.failure.empty()) failed.push_back(row.engine);
      std::cerr << "compare: " << engines::join_names(failed, "and")
                << (failed.size() == 1 ? " failed" : " failed each")
                << "; its row in metrics.csv gives the reason (exit 4)\n";
      return kExitEngineFailed;
    }
    return 0;
  }

 private:
  std::string name_;
  std::vector<std::string> engines_;
  std::optional<double> dt_;
  std::optional<double> duration_;
  std::vector<std::string> sets_;
  std::vector<std::string> options_;
  std::filesystem::path out_;
  std::string settings_set_;
  bool no_plots_ = false;
};

}  // namespace

std::unique_ptr<Command> add_compare_command(CLI::App& app) {
  return std::make_unique<CompareCommand>(
      app.add_subcommand("compare", "Run several engines on one scenario and compare them"));
}

}  // namespace impactbench::cli
