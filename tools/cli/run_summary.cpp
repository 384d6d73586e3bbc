#include "tools/cli/run_summary.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "lib/metrics/run_figures.hpp"
#include "lib/output/number_text.hpp"
#include "tools/engines/registry/run_settings.hpp"

namespace impactbench::cli {

void print_run_summary(const scenario::Scenario& scenario, const engines::RunOptions& options,
                       const engines::RunResult& result) {
  std::printf("%s on %s\n", result.engine.c_str(), scenario.name.c_str());
  std::printf("  setting duration %s (%s)\n", output::number_text(options.duration).c_str(),
              to_string(options.duration_source).c_str());
  for (const auto& setting : result.settings)
    std::printf("  setting %s %s (%s)\n", setting.key.c_str(), setting.value.c_str(),
                to_string(setting.source).c_str());
  if (options.settings_set == engines::SettingsSet::kExpert)
    std::printf("  settings set expert: %s\n",
                engines::applies_settings_set(options.engine, options.settings_set)
                    ? "the values marked (expert) come from it"
                    : (result.engine + " has none; its defaults are in force").c_str());
  std::printf("  samples %ld\n", result.sample_count);
  // The figures of metrics.csv, under the same names (docs/cli.md).
  for (const auto& [name, value] : metrics::run_figures(result)) {
    if (std::isnan(value))
      std::printf("  %-20s - (%s)\n", name.c_str(), result.unconverged_note.c_str());
    else
      std::printf("  %-20s %s\n", name.c_str(), output::number_text(value).c_str());
  }
  std::map<std::string, int> kinds;
  for (const auto& event : result.events) ++kinds[event.kind];
  std::printf("  events %zu", result.events.size());
  for (const auto& [kind, count] : kinds) std::printf(", %s %d", kind.c_str(), count);
  std::printf("\n");
  std::printf("  max_penetration      %s m (every contact found in every recorded state)\n",
              output::number_text(result.max_penetration).c_str());
  if (result.sample_count > 0)
    std::printf("  energy %s J at start, %s J at end\n",
                output::number_text(result.first_energy).c_str(),
                output::number_text(result.last_energy).c_str());
  if (result.unconverged_steps.value_or(0) > 0)
    std::printf("  warning: %ld steps not solved to tolerance (worst residual %s)\n",
                *result.unconverged_steps,
                output::number_text(result.worst_unconverged_residual).c_str());
  if (!result.defect_note.empty()) std::printf("  warning: %s\n", result.defect_note.c_str());
  for (const auto& [key, value] : result.summary)
    std::printf("  %s %s\n", key.c_str(), value.c_str());
}

}  // namespace impactbench::cli
