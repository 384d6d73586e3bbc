#pragma once
// What `impactbench compare` checks before any engine runs, as a library call that the program
// and the Python module share: bare --option keys refused (compare runs several engines), no
// engine named twice, every engine named able to run the scenario and built, each engine's
// settings resolved (compare::resolve_compare_runs).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"
#include "tools/compare/compare.hpp"

namespace impactbench::cli {

/// The arguments of `compare` other than the scenario and plots, as given on the command line.
struct CompareRequest {
  std::vector<std::string> engines;  ///< --engines; empty: every available one
  std::optional<double> dt;
  std::optional<double> duration;
  std::vector<std::string> options;  ///< --option ENGINE.key=value
  std::filesystem::path out;
  std::string settings_set;  ///< --settings: "", "default" or "expert"
};

/// The options of compare::run_compare (without plots); throws CliError with the program's
/// message and exit code.
compare::CompareOptions compare_options(const scenario::Scenario& s, const CompareRequest& request);

}  // namespace impactbench::cli
