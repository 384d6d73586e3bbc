#include "tools/compare/work_precision.hpp"

#include "tools/engines/engine_names.hpp"

namespace impactbench::compare {

std::string work_precision_knob(const std::string& engine) {
  return engine == engine_name::kEvent ? "tol" : "dt";
}

std::vector<double> work_precision_values(const std::string& knob, bool quick) {
  if (knob == "tol")
    return quick ? std::vector<double>{1e-4, 1e-8, 1e-12}
                 : std::vector<double>{1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
  return quick ? std::vector<double>{4e-3, 1e-3, 2.5e-4}
               : std::vector<double>{8e-3, 4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4};
}

}  // namespace impactbench::compare
