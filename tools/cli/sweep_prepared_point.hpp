#pragma once
// A sweep point made ready to run the way `impactbench compare --engines ENGINE` runs it: the
// scenario with the point's --set values, compare's options (compare_request.hpp) with its dt,
// tolerance, solver and --option values, every setting resolved; and the hash of what
// determines its result: the scenario file's content, the settings in force and the program's
// version.
#include <filesystem>
#include <string>

#include "lib/scenario/scenario.hpp"
#include "tools/cli/sweep_points.hpp"
#include "tools/cli/sweep_result.hpp"
#include "tools/compare/compare.hpp"

namespace impactbench::cli {

/// The program version that goes into every point's hash.
std::string program_version();

struct PreparedPoint {
  scenario::Scenario scenario;
  compare::CompareOptions options;
  std::string settings;  ///< compare::settings_text of the run, as in metrics.csv
  std::string hash;
};

/// Throws CliError or ScenarioError for what the point cannot be run with (its scenario,
/// engine, a value); `scratch` is where compare writes its files.
PreparedPoint prepare_point(const SweepSpec& spec, const SweepPoint& point,
                            const std::filesystem::path& scratch);

/// Runs the point through compare::run_compare (one engine, no plots); a failed engine run is
/// a result with status failed and its reason. Removes `scratch` afterwards.
PointResult run_prepared_point(const SweepPoint& point, PreparedPoint& prepared);

/// A worker's job: prepares and runs `point` of `spec` and writes its result into `dir` (a
/// failed run is a result); throws what preparing it throws.
void run_planned_point(const SweepSpec& spec, const SweepPoint& point,
                       const std::filesystem::path& dir);

/// `impactbench sweep-point`: finds point `id` of the sweep file `spec` and runs it as a worker
/// does. Throws CliError (exit 2) when the file has no such point.
void run_sweep_point(const std::filesystem::path& spec, const std::filesystem::path& dir,
                     const std::string& id);

}  // namespace impactbench::cli
