#pragma once
// What `impactbench run` checks and resolves before asking an engine, as a library call that
// the program and the Python module share: the scenario with its overrides, the engine it can
// be run by, every setting through engines::resolve_run_options, the sample interval and the
// recording that keeps the trajectory at most about kDefaultMaxValues numbers.
#include <optional>
#include <string>
#include <vector>

#include "lib/engines/run_result.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/engines/registry/engine_registry.hpp"

namespace impactbench::cli {

/// The trajectory of `run` holds about at most this many numbers (rows × columns) unless a
/// sample interval says otherwise (docs/cli.md).
inline constexpr double kDefaultMaxValues = 1e6;

/// The arguments of `run` other than its output files, as given on the command line.
struct RunRequest {
  std::string scenario;
  std::string engine;
  std::optional<double> dt;
  std::optional<double> tolerance;
  std::optional<std::string> solver;
  std::optional<double> duration;
  std::vector<std::string> sets;     ///< --set name=value
  std::vector<std::string> options;  ///< --option [ENGINE.]key=value
  std::optional<double> sample_dt;   ///< --sample-dt; 0 = every step
  std::string settings_set;          ///< --settings: "", "default" or "expert"
};

/// The scenario and the run's options, every setting resolved.
struct PreparedRun {
  scenario::Scenario scenario;
  engines::RunOptions options;
};

/// Loads the scenario, checks the engine can run it, resolves the settings and checks the
/// sample interval; throws CliError with the program's message and exit code.
PreparedRun prepare_run(const RunRequest& request);

/// The registry's entry of an engine that is built; throws CliError (usage) otherwise.
const adapters::EngineInfo& built_engine(const std::string& engine);

/// The sampling of `run`: every sample_dt, or (when unset, for a time-stepper) every step while
/// the trajectory holds at most kDefaultMaxValues numbers; keeps neither samples nor steps in
/// memory (the caller's sample_sink receives the samples).
engines::RecordingOptions run_recording(const std::string& engine, double duration,
                                        std::optional<double> sample_dt);

}  // namespace impactbench::cli
