// Finding scenario files: by name in the scenario directory, which is share/impactbench/scenarios
// beside the program unless the environment variable IMPACTBENCH_SCENARIOS points elsewhere.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include "lib/output/message_text.hpp"
#include "lib/resources/resource_paths.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::scenario {

std::filesystem::path scenario_directory() {
  return resources::scenario_directory();
}

std::vector<std::string> list_scenarios() {
  const auto directory = scenario_directory();
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error))
    throw std::runtime_error("scenario directory " + directory.string() + " does not exist");
  std::vector<std::string> names;
  for (std::filesystem::directory_iterator it(directory, error), end; !error && it != end;
       it.increment(error)) {
    if (it->path().extension() != ".toml") continue;
    // One broken entry (a symbolic link loop, a dangling link) must not hide the others.
    std::error_code entry_error;
    const bool regular = it->is_regular_file(entry_error);
    if (entry_error) {
      std::cerr << "impactbench: warning: skipping " << output::printable(it->path().string())
                << ": " << entry_error.message() << '\n';
      continue;
    }
    if (regular) names.push_back(it->path().stem().string());
  }
  if (error)
    throw std::runtime_error("cannot list the scenario directory " + directory.string() + ": " +
                             error.message());
  std::sort(names.begin(), names.end());
  return names;
}

Scenario load_scenario_by_name(const EngineCatalog& engines, const std::string& name,
                               const ParameterOverrides& overrides,
                               std::optional<double> duration) {
  const auto path = scenario_directory() / (name + ".toml");
  const auto names = list_scenarios();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    std::string available;
    for (const auto& n : names) available += (available.empty() ? "" : ", ") + n;
    throw ScenarioError(scenario_directory().string(), 0, name,
                        "no such scenario (available: " + available + ")");
  }
  return load_scenario(engines, path, overrides, duration);
}

std::pair<std::string, double> parse_override(const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw std::invalid_argument("--set expects name=value, got '" + assignment + "'");
  const std::string name = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
    throw std::invalid_argument("--set " + name + ": '" + text + "' is not a finite number");
  return {name, value};
}

}  // namespace impactbench::scenario
