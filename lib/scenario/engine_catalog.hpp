#pragma once
// What the scenario loader checks a file's `engines` list and its [settings.ENGINE] tables
// against. The loader knows no engine itself: the engine registry is the catalog every program
// and test loads with (the registry's scenario_loading.hpp), so that the engines' names are
// listed in one place and the scenario code includes no engine.
#include <string>
#include <vector>

namespace impactbench::scenario {

class EngineCatalog {
 public:
  virtual ~EngineCatalog() = default;
  /// Every engine's name, in the order they are listed to users.
  virtual const std::vector<std::string>& engine_names() const = 0;
  /// Empty when `key = value` may stand in [settings.<engine>] of a scenario whose duration is
  /// `duration` (`engine` one of engine_names()); else why not, e.g. "must be in [0.5, 1], got
  /// '2'", as the end of a message that names file, line and field.
  virtual std::string setting_problem(const std::string& engine, const std::string& key,
                                      const std::string& value, double duration) const = 0;
  /// Empty when the scenario's own `dt` or `tolerance` (`field`) may be what `engine` takes as
  /// its step or tolerance (an engine without one ignores it); else why not, likewise.
  virtual std::string run_value_problem(const std::string& engine, const std::string& field,
                                        double value, double duration) const = 0;
};

}  // namespace impactbench::scenario
