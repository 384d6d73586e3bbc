#include "tools/cli/suite_real_tosses.hpp"

#include <chrono>
#include <sstream>

#include "lib/resources/resource_paths.hpp"
#include "tools/cli/validation_parameters.hpp"
#include "tools/cli/validation_plots.hpp"
#include "tools/cli/validation_report.hpp"
#include "tools/cli/validation_study.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

constexpr std::size_t kQuickTosses = 10;

/// `markdown` with every heading `levels` levels down, to sit under the suite's own.
std::string nested(const std::string& markdown, int levels) {
  std::istringstream in(markdown);
  std::string out;
  for (std::string line; std::getline(in, line);)
    out += (line.rfind('#', 0) == 0 ? std::string(static_cast<std::size_t>(levels), '#') : "") +
           line + "\n";
  return out;
}

/// One validation of the section at a parameter set ("default" or "fitted") of `request` (its
/// engines and tosses), its outputs in dir/set; its summary and plots as Markdown whose links
/// are relative to dir's parent.
std::string validation_at(const std::string& set, ValidationRequest request, bool quick,
                          const std::filesystem::path& dir, bool plots) {
  ValidationHeader header;
  header.parameter_set = set;
  if (set == "fitted") header.table = apply_parameter_table(request, fitted_parameters_path());
  const auto start = std::chrono::steady_clock::now();
  const std::vector<TossRun> runs = run_validation(request);
  header.data = "scenarios/data/cube_toss/tosses";
  header.selection = quick
                         ? "test (the first " + std::to_string(request.tosses.size()) + ", --quick)"
                         : std::string("test");
  header.initial_state = "sample";
  header.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string summary = validation_summary(header, request.engines, runs);
  const std::filesystem::path out = dir / set;
  std::filesystem::create_directories(out);
  write_validation_outputs(out, summary, request.engines, runs, request.tosses.front());
  std::string markdown = nested(summary, 2);
  if (plots) {
    plot_validation(resources::python_interpreter(), resources::scripts_directory(), out);
    for (const std::string& png : validation_plot_names())
      markdown += "\n![" + set + ": " + png + "](" + dir.filename().string() + "/" + set + "/" +
                  png + ")\n";
  }
  return markdown;
}

}  // namespace

std::string real_tosses_section(bool quick, const std::filesystem::path& dir, bool plots) {
  ValidationRequest request;
  request.engines = cube_toss_engines(scenario::load_scenario_by_name("cube_toss"));
  request.tosses =
      read_tosses(resources::cube_toss_directory(), "test", quick ? kQuickTosses : SIZE_MAX);
  request.traced_toss = request.tosses.front().name;
  // One after the other (the operands of + have no evaluation order).
  const std::string by_default = validation_at("default", request, quick, dir, plots);
  const std::string fitted = validation_at("fitted", request, quick, dir, plots);
  return "## Real tosses\n\nEvery spatial engine from the first sample of each recorded test "
         "toss (docs/real-tosses.md), at the scenario's default parameters and at each engine's "
         "fitted ones (scenarios/data/cube_toss/fitted_parameters.toml).\n\n" +
         by_default + "\n" + fitted;
}

}  // namespace impactbench::cli
