#pragma once
// The engines `impactbench run --engine NAME` can use. Every name of
// scenario::known_engines() has an entry; an entry without a function is an engine that is
// not built yet. Engines plug in by filling their entry in engine_registry.cpp.
#include <string>
#include <vector>

#include "lib/scenario/engine_run.hpp"

namespace impactbench::cli {

struct EngineEntry {
  std::string name;
  std::string description;
  scenario::EngineFunction run;  ///< empty: not available yet
};

const std::vector<EngineEntry>& engine_registry();
/// nullptr for an unknown name.
const EngineEntry* find_engine(const std::string& name);

}  // namespace impactbench::cli
