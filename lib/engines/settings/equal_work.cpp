#include "lib/engines/settings/equal_work.hpp"

namespace impactbench::engines {

std::vector<std::pair<std::string, std::string>> equal_work_settings(const std::string& engine) {
  if (engine == "moreau")
    return {{"solver", "nsgs"},
            {"max_iterations", "10"},
            {"on_failure", "warn"},
            {"cold_restart", "false"}};
  if (engine == "box2d") return {{"velocity_iterations", "8"}, {"position_iterations", "3"}};
  if (engine == "bullet") return {{"solver_iterations", "10"}};
  return {};
}

const std::vector<std::string>& equal_work_engines() {
  static const std::vector<std::string> engines = {"moreau", "box2d", "bullet"};
  return engines;
}

}  // namespace impactbench::engines
