#pragma once
// `impactbench validate`'s work: every engine from every selected recorded toss on the
// cube_toss scenario, each run scored against its recording (lib/validation). A run that fails
// is kept with its reason, never dropped.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lib/scenario/scenario.hpp"
#include "lib/validation/score_statistics.hpp"
#include "lib/validation/toss.hpp"
#include "lib/validation/toss_score.hpp"

namespace impactbench::cli {

enum class InitialStateKind { kSample, kFit };

struct ValidationRequest {
  std::vector<std::string> engines;  ///< checked names, in order
  std::vector<validation::Toss> tosses;
  InitialStateKind initial_state = InitialStateKind::kSample;
  scenario::ParameterOverrides overrides;  ///< --set (never the state parameters)
  /// An engine's own parameters (--parameters), under `overrides`.
  std::map<std::string, scenario::ParameterOverrides> engine_overrides;
  /// --option ENGINE.key=value: engine → its key=value pairs (checked by check_validation_options).
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> options;
  /// The toss whose simulated poses every run keeps (for the trajectory plot); empty: none.
  std::string traced_toss;
  /// Called after each run with the simulated time done so far and in all.
  std::function<void(double done, double total)> progress;
};

struct TossRun {
  std::string engine;
  std::string toss;
  std::string failure;  ///< empty: scored
  validation::TossScore score;
  std::vector<validation::SampleError> errors;   ///< per recorded sample (scored runs)
  std::vector<validation::SimulatedPose> poses;  ///< at the samples: the traced toss only
  double wall_seconds = 0.0;
};

/// The scenario validate runs, with `overrides` and the toss's state (sample 0 or the fit);
/// duration from the state's time to the toss's last sample. Throws what loading or the fit
/// throws.
scenario::Scenario toss_scenario(const validation::Toss& toss, InitialStateKind kind,
                                 const scenario::ParameterOverrides& overrides);

/// The tosses of `data` (a folder of toss CSV files) that `selection` (--tosses: test, train,
/// all, or numbers and ranges) selects, the first `at_most` of them. Throws CliError: exit 2
/// for a bad selection or a folder that is not one, exit 1 for a bad file (`path:line: what`)
/// or none selected.
std::vector<validation::Toss> read_tosses(const std::filesystem::path& data,
                                          const std::string& selection,
                                          std::size_t at_most = SIZE_MAX);

/// The parameters `engine` runs with: its engine_overrides, then the request's overrides.
scenario::ParameterOverrides engine_parameters(const ValidationRequest& request,
                                               const std::string& engine);

/// The engines validate runs by default: every built engine that `cube_toss` lists.
std::vector<std::string> cube_toss_engines(const scenario::Scenario& cube_toss);

/// Throws CliError (usage) naming the engine and key when an engine refuses one of its
/// `options` on `cube_toss` (loaded with the request's overrides); checked once, before any
/// toss runs.
void check_validation_options(
    const scenario::Scenario& cube_toss,
    const std::map<std::string, std::vector<std::pair<std::string, std::string>>>& options);

/// One engine's runs summed up: per score (validation::score_names order) its statistics over
/// the scored tosses, and each failed toss with its reason ("toss: reason").
struct EngineScores {
  std::vector<validation::Statistics> scores;
  std::vector<std::string> failures;
};
EngineScores engine_scores(const std::vector<TossRun>& runs, const std::string& engine);

/// Runs and scores every engine on every toss, engines outermost.
std::vector<TossRun> run_validation(const ValidationRequest& request);

}  // namespace impactbench::cli
