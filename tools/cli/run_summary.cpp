#include "tools/cli/run_summary.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include "lib/output/number_text.hpp"

namespace impactbench::cli {

void print_run_summary(const scenario::Scenario& scenario, const engines::RunOptions& options,
                       const engines::RunResult& result) {
  std::printf("%s on %s\n", result.engine.c_str(), scenario.name.c_str());
  std::printf("  setting duration %s (%s)\n", output::number_text(options.duration).c_str(),
              to_string(options.duration_source).c_str());
  for (const auto& setting : result.settings)
    std::printf("  setting %s %s (%s)\n", setting.key.c_str(), setting.value.c_str(),
                to_string(setting.source).c_str());
  const auto& samples = result.trajectory.samples;
  std::printf("  samples %zu, steps %zu, CPU %.4g s\n", samples.size(), result.steps.size(),
              result.cpu_seconds);
  std::map<std::string, int> kinds;
  for (const auto& event : result.events) ++kinds[event.kind];
  std::printf("  events %zu", result.events.size());
  for (const auto& [kind, count] : kinds) std::printf(", %s %d", kind.c_str(), count);
  std::printf("\n");
  double penetration = 0.0, worst_residual = 0.0;
  int failures = 0;
  for (const auto& step : result.steps) {
    for (const auto& contact : step.contacts) penetration = std::max(penetration, -contact.gap);
    if (!step.converged) {
      ++failures;
      worst_residual = std::max(worst_residual, step.residual);
    }
  }
  std::printf("  max penetration %s m\n", output::number_text(penetration).c_str());
  if (!samples.empty())
    std::printf("  energy %s J at start, %s J at end\n",
                output::number_text(samples.front().energy).c_str(),
                output::number_text(samples.back().energy).c_str());
  if (failures > 0)
    std::printf("  solver failures %d (worst residual %s)\n", failures,
                output::number_text(worst_residual).c_str());
  for (const auto& [key, value] : result.summary)
    std::printf("  %s %s\n", key.c_str(), value.c_str());
}

}  // namespace impactbench::cli
