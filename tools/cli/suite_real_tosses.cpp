#include "tools/cli/suite_real_tosses.hpp"

#include <chrono>
#include <sstream>

#include "lib/resources/resource_paths.hpp"
#include "tools/cli/validation_report.hpp"
#include "tools/cli/validation_study.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

constexpr std::size_t kQuickTosses = 10;

/// `markdown` with every heading one level down, to sit under the suite's own.
std::string nested(const std::string& markdown) {
  std::istringstream in(markdown);
  std::string out;
  for (std::string line; std::getline(in, line);)
    out += (line.rfind('#', 0) == 0 ? "#" : "") + line + "\n";
  return out;
}

}  // namespace

std::string real_tosses_section(bool quick, const std::filesystem::path& dir) {
  const scenario::Scenario base = scenario::load_scenario_by_name("cube_toss");
  ValidationRequest request;
  request.engines = cube_toss_engines(base);
  request.tosses =
      read_tosses(resources::cube_toss_directory(), "test", quick ? kQuickTosses : SIZE_MAX);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<TossRun> runs = run_validation(request);
  ValidationHeader header;
  header.data = "scenarios/data/cube_toss/tosses";
  header.selection = quick
                         ? "test (the first " + std::to_string(request.tosses.size()) + ", --quick)"
                         : std::string("test");
  header.initial_state = "sample";
  header.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string summary = validation_summary(header, request.engines, runs);
  std::filesystem::create_directories(dir);
  write_validation_outputs(dir, summary, runs);
  return nested(summary);
}

}  // namespace impactbench::cli
