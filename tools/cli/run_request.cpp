#include "tools/cli/run_request.hpp"

#include <stdexcept>

#include "lib/engines/step_count.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

// Every setting through the one place (engines::resolve_run_options); whatever it refuses was
// given by the caller, so it is a usage error.
engines::RunOptions resolve_options(const RunRequest& request, const scenario::Scenario& s) {
  engines::SettingsRequest settings;
  settings.dt = request.dt;
  settings.tolerance = request.tolerance;
  settings.solver = request.solver;
  settings.duration = request.duration;
  settings.set = settings_set_of(request.settings_set);
  settings.options =
      options_for(parse_option_entries(request.options), request.engine, true, {request.engine});
  try {
    return engines::resolve_run_options(request.engine, s, settings);
  } catch (const std::invalid_argument& error) {
    throw CliError(error.what(), kExitUsage);
  }
}

// An interval so small that duration / interval leaves the doubles' exact range (a subnormal
// 5e-324 overflows it) would thin the rows instead of keeping each: refused like a step.
void check_sample_interval(std::optional<double> sample_dt, double duration) {
  if (!sample_dt || *sample_dt == 0.0 || !(duration > 0.0)) return;
  try {
    engines::checked_step_count("--sample-dt", duration, *sample_dt, "sample interval");
  } catch (const std::invalid_argument& error) {
    throw CliError(error.what(), kExitUsage);
  }
}

}  // namespace

PreparedRun prepare_run(const RunRequest& request) {
  auto s = scenario::load_scenario_by_name(request.scenario, parse_overrides(request.sets),
                                           request.duration);
  if (!s.supports_engine(request.engine))
    throw CliError("scenario '" + s.name + "' cannot be run by engine '" + request.engine +
                       "' (its engines: " + engines::join_names(s.engines, "and") + ")",
                   kExitFailure);
  engines::RunOptions options = resolve_options(request, s);
  check_sample_interval(request.sample_dt, options.duration);
  return {std::move(s), std::move(options)};
}

const adapters::EngineInfo& built_engine(const std::string& engine) {
  const adapters::EngineInfo* info = adapters::find_engine(engine);
  if (!info || !info->run) throw CliError(adapters::not_built_message(engine), kExitUsage);
  return *info;
}

engines::RecordingOptions run_recording(const std::string& engine, double duration,
                                        std::optional<double> sample_dt) {
  engines::RecordingOptions recording;
  recording.keep_samples = false;
  recording.keep_steps = false;
  recording.sample_interval = sample_dt.value_or(0.0);
  // The budget thins the steps of a time-stepper; the event engine samples at its own
  // output_interval and at events, which it keeps.
  const engines::EngineSettings* settings = engines::find_engine_settings(engine);
  if (!sample_dt && settings && !settings->dt_keys.empty())
    recording.max_values = kDefaultMaxValues;
  recording.duration = duration;
  return recording;
}

}  // namespace impactbench::cli
