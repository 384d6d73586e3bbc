#include "tools/cli/run_summary.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

namespace impactbench::cli {

void print_run_summary(const scenario::Scenario& scenario, const engines::RunResult& result) {
  std::printf("%s on %s\n", result.engine.c_str(), scenario.name.c_str());
  for (const auto& [key, value] : result.settings)
    std::printf("  setting %-28s %s\n", key.c_str(), value.c_str());
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
  std::printf("  max penetration %.3g m\n", penetration);
  if (!samples.empty())
    std::printf("  energy %.10g J at start, %.10g J at end\n", samples.front().energy,
                samples.back().energy);
  if (failures > 0)
    std::printf("  solver failures %d (worst residual %.3g)\n", failures, worst_residual);
  for (const auto& [key, value] : result.summary)
    std::printf("  %s %s\n", key.c_str(), value.c_str());
}

}  // namespace impactbench::cli
