#include "tools/cli/engine_registry.hpp"

namespace impactbench::cli {

const std::vector<EngineEntry>& engine_registry() {
  // Fill `run` when an engine lands, e.g. {"moreau", "...", &moreau::run_scenario}.
  static const std::vector<EngineEntry> engines = {
      {"moreau", "Moreau-Jean time-stepping (event-capturing), one contact problem per step", {}},
      {"event", "event-driven hybrid integration (event-tracking) with located guards", {}},
      {"box2d", "Box2D 2.4 reference scene (planar scenarios)", {}},
      {"bullet", "Bullet 3 reference scene, double precision (spatial scenarios)", {}},
  };
  return engines;
}

const EngineEntry* find_engine(const std::string& name) {
  for (const auto& entry : engine_registry())
    if (entry.name == name) return &entry;
  return nullptr;
}

}  // namespace impactbench::cli
