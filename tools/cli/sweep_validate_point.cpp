#include "tools/cli/sweep_validate_point.hpp"

#include "lib/engines/run_timer.hpp"
#include "lib/validation/score_statistics.hpp"
#include "lib/validation/toss_score.hpp"
#include "lib/validation/toss_state.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/run_request.hpp"
#include "tools/cli/validation_study.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {
namespace {

scenario::ParameterOverrides overrides_of(const SweepPoint& point) {
  std::vector<std::string> assignments;
  for (const auto& [name, value] : point.sets) assignments.push_back(name + "=" + value);
  return parse_overrides(assignments);
}

}  // namespace

PreparedPoint prepare_validate_point(const SweepSpec& spec, const SweepPoint& point) {
  const scenario::ParameterOverrides overrides = overrides_of(point);
  for (const auto& [name, unused] : overrides)
    if (validation::is_state_parameter(name))
      throw CliError("the initial state comes from each toss; it cannot be swept", kExitUsage);
  PreparedPoint prepared{scenario::load_scenario_by_name("cube_toss", overrides), {}, {}, {}};
  const adapters::EngineInfo& info = built_engine(point.engine);
  if (!prepared.scenario.supports_engine(info.name))
    throw CliError("cube_toss does not list " + point.engine, kExitUsage);
  if (!point.options.empty())
    check_validation_options(prepared.scenario, {{point.engine, point.options}});
  const SpecValidate& validate = *spec.validate;
  prepared.settings =
      "validate tosses=" + validate.tosses + " initial_state=" + validate.initial_state +
      " data=" + (validate.data.empty() ? std::string("shipped") : validate.data.string());
  return prepared;
}

PointResult run_validate_point(const SweepSpec& spec, const SweepPoint& point,
                               const PreparedPoint& prepared) {
  const SpecValidate& validate = *spec.validate;
  ValidationRequest request;
  request.engines = {point.engine};
  request.overrides = overrides_of(point);
  if (!point.options.empty()) request.options[point.engine] = point.options;
  request.initial_state =
      validate.initial_state == "fit" ? InitialStateKind::kFit : InitialStateKind::kSample;
  const double start = engines::process_cpu_seconds();
  request.tosses = read_tosses(validate.folder(), validate.tosses);
  const std::vector<TossRun> runs = run_validation(request);

  PointResult result{
      point.id, prepared.hash, "ok", "", "recorded tosses (" + validate.tosses + ")", 0, {}};
  const auto& names = validation::score_names();
  const EngineScores summed = engine_scores(runs, point.engine);
  result.metrics.emplace_back("scored", static_cast<double>(summed.scores.front().count));
  result.metrics.emplace_back("failed", static_cast<double>(summed.failures.size()));
  for (std::size_t m = 0; m < names.size(); ++m) {
    const validation::Statistics& s = summed.scores[m];
    result.metrics.emplace_back(names[m] + "_mean", s.mean);
    result.metrics.emplace_back(names[m] + "_median", s.median);
    result.metrics.emplace_back(names[m] + "_p90", s.p90);
  }
  if (summed.scores.front().count == 0) {
    result.status = "failed";
    result.reason =
        "no toss scored" +
        (summed.failures.empty() ? std::string() : " (" + summed.failures.front() + ")");
  }
  result.cpu_seconds = engines::process_cpu_seconds() - start;
  return result;
}

}  // namespace impactbench::cli
