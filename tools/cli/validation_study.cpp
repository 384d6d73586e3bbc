#include "tools/cli/validation_study.hpp"

#include <chrono>
#include <exception>
#include <utility>

#include "lib/validation/toss_csv.hpp"
#include "lib/validation/toss_selection.hpp"
#include "lib/validation/toss_state.hpp"
#include "tools/cli/command.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

validation::CubeGeometry geometry(const scenario::Scenario& s) {
  validation::CubeGeometry cube;
  cube.side = s.parameter("side");
  cube.board_offset = s.parameter("board_offset");
  return cube;
}

TossRun run_one(const std::string& engine, const validation::Toss& toss,
                const ValidationRequest& request) {
  TossRun run{engine, toss.name, "", {}, {}, {}, 0.0};
  const auto start = std::chrono::steady_clock::now();
  try {
    const scenario::Scenario s =
        toss_scenario(toss, request.initial_state, engine_parameters(request, engine));
    engines::SettingsRequest settings;
    if (const auto given = request.options.find(engine); given != request.options.end())
      settings.options = given->second;
    engines::RunOptions options = engines::resolve_run_options(engine, s, settings);
    options.recording.keep_steps = false;
    const engines::RunResult result = adapters::run_engine(engine, s, options);
    auto poses = validation::poses_at_samples(result.trajectory, "cube", toss, 0);
    run.score = validation::score_toss(toss, 0, poses, geometry(s));
    run.errors = validation::sample_errors(toss, 0, poses, geometry(s));
    if (toss.name == request.traced_toss) run.poses = std::move(poses);
  } catch (const std::exception& error) {
    run.failure = error.what();
  }
  run.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace

scenario::Scenario toss_scenario(const validation::Toss& toss, InitialStateKind kind,
                                 const scenario::ParameterOverrides& overrides) {
  const scenario::Scenario base = scenario::load_scenario_by_name("cube_toss", overrides);
  const validation::InitialState state =
      kind == InitialStateKind::kFit
          ? validation::fitted_state(toss, geometry(base), base.parameter("g"))
          : validation::sample_state(toss, 0);
  scenario::ParameterOverrides all = overrides;
  for (const auto& [name, value] : validation::state_parameters(state)) all[name] = value;
  return scenario::load_scenario_by_name("cube_toss", all, toss.samples.back().t - state.t);
}

scenario::ParameterOverrides engine_parameters(const ValidationRequest& request,
                                               const std::string& engine) {
  scenario::ParameterOverrides all;
  if (const auto own = request.engine_overrides.find(engine); own != request.engine_overrides.end())
    all = own->second;
  for (const auto& [name, value] : request.overrides) all[name] = value;
  return all;
}

std::vector<validation::Toss> read_tosses(const std::filesystem::path& data,
                                          const std::string& selection, std::size_t at_most) {
  validation::TossSelection selected;
  try {
    selected = validation::parse_toss_selection(selection);
  } catch (const std::invalid_argument& error) {
    throw CliError(error.what(), kExitUsage);
  }
  std::error_code error;
  if (!std::filesystem::is_directory(data, error))
    throw CliError("--data " + data.string() + ": not a directory", kExitUsage);
  auto files = validation::select_toss_files(data, selected);
  if (files.empty())
    throw CliError(
        "no toss file (*.csv) of " + data.string() + " is selected by --tosses " + selection,
        kExitFailure);
  if (files.size() > at_most) files.resize(at_most);
  std::vector<validation::Toss> tosses;
  for (const auto& file : files) {
    try {
      tosses.push_back(validation::read_toss(file));
    } catch (const validation::TossDataError& bad) {
      throw CliError(bad.what(), kExitFailure);
    }
  }
  return tosses;
}

std::vector<std::string> cube_toss_engines(const scenario::Scenario& cube_toss) {
  std::vector<std::string> names;
  for (const auto& info : adapters::engine_registry())
    if (info.run && cube_toss.supports_engine(info.name)) names.push_back(info.name);
  return names;
}

void check_validation_options(
    const scenario::Scenario& cube_toss,
    const std::map<std::string, std::vector<std::pair<std::string, std::string>>>& options) {
  for (const auto& [engine, given] : options) {
    engines::SettingsRequest settings;
    settings.options = given;
    try {
      engines::resolve_run_options(engine, cube_toss, settings);
    } catch (const std::invalid_argument& error) {
      throw CliError(error.what(), kExitUsage);
    }
  }
}

EngineScores engine_scores(const std::vector<TossRun>& runs, const std::string& engine) {
  const auto& names = validation::score_names();
  std::vector<std::vector<double>> values(names.size());
  EngineScores out;
  for (const TossRun& run : runs) {
    if (run.engine != engine) continue;
    if (!run.failure.empty()) {
      out.failures.push_back(run.toss + ": " + run.failure);
      continue;
    }
    const auto v = validation::score_values(run.score);
    for (std::size_t m = 0; m < names.size(); ++m) values[m].push_back(v[m]);
  }
  for (const auto& metric : values) out.scores.push_back(validation::statistics(metric));
  return out;
}

std::vector<TossRun> run_validation(const ValidationRequest& request) {
  double total = 0.0;
  for (const auto& toss : request.tosses)
    total += (toss.samples.back().t - toss.samples.front().t) *
             static_cast<double>(request.engines.size());
  double done = 0.0;
  std::vector<TossRun> runs;
  for (const std::string& engine : request.engines)
    for (const validation::Toss& toss : request.tosses) {
      runs.push_back(run_one(engine, toss, request));
      done += toss.samples.back().t - toss.samples.front().t;
      if (request.progress) request.progress(done, total);
    }
  return runs;
}

}  // namespace impactbench::cli
