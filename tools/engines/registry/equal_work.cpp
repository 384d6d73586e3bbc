#include "tools/engines/registry/equal_work.hpp"

#include "tools/engines/registry/engine_registry.hpp"

namespace impactbench::engines {

std::vector<std::pair<std::string, std::string>> equal_work_settings(const std::string& engine) {
  const adapters::EngineInfo* info = adapters::find_engine(engine);
  return info ? info->equal_work : std::vector<std::pair<std::string, std::string>>{};
}

const std::vector<std::string>& equal_work_engines() {
  static const std::vector<std::string> engines = [] {
    std::vector<std::string> out;
    for (const adapters::EngineInfo& info : adapters::engine_registry())
      if (!info.equal_work.empty()) out.push_back(info.name);
    return out;
  }();
  return engines;
}

double bare_loop_seconds_per_step(const scenario::Scenario& scenario, RunOptions options) {
  options.recording = {};
  options.recording.keep_samples = false;
  options.recording.keep_steps = false;
  options.recording.timing_only = true;
  const RunResult run = adapters::run_engine(options.engine, scenario, options);
  return run.engine_cpu_seconds / static_cast<double>(run.step_count);
}

}  // namespace impactbench::engines
