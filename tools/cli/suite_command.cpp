// `impactbench suite [--out DIR] [--quick]`: the default benchmark suite on the shipped
// scenarios (see tools/compare/suite.hpp); the README's first quick-start command.
#include <iostream>

#include "lib/resources/resource_paths.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/suite_real_tosses.hpp"
#include "tools/cli/suite_work_precision.hpp"
#include "tools/compare/suite.hpp"

namespace impactbench::cli {
namespace {

class SuiteCommand : public Command {
 public:
  explicit SuiteCommand(CLI::App* app) : Command(app) {
    app->add_option("--out", options_.out, "Output directory (default: results)");
    app->add_flag("--quick", options_.quick,
                  "The 2-minute version: fewer sweep points, no piles, short runs");
    app->add_flag("--no-plots", no_plots_, "Skip the matplotlib plots");
  }

  int run() override {
    options_.python_for_scripts = resources::python_interpreter();
    options_.tools_dir = resources::scripts_directory();
    if (!no_plots_) options_.python = resources::python_interpreter();
    options_.bench_dir = resources::benchmark_directory();
    options_.work_precision = [](const scenario::Scenario& s, const std::string& quantity,
                                 bool quick, const std::filesystem::path& dir,
                                 const std::function<void(const std::string&)>& note) {
      return work_precision_by_sweep(s, quantity, quick, dir, note);
    };
    options_.real_tosses = real_tosses_section;
    const auto summary = compare::run_suite(options_);
    std::cout << "summary: " << summary.string() << "\n";
    return 0;
  }

 private:
  compare::SuiteOptions options_;
  bool no_plots_ = false;
};

}  // namespace

std::unique_ptr<Command> add_suite_command(CLI::App& app) {
  return std::make_unique<SuiteCommand>(app.add_subcommand(
      "suite", "Run the default benchmark suite on the shipped scenarios → DIR/summary.md"));
}

}  // namespace impactbench::cli
