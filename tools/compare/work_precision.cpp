#include "tools/compare/work_precision.hpp"

#include <cmath>
#include <exception>
#include <limits>
#include <string>

#include "lib/output/number_text.hpp"
#include "tools/compare/analytic_errors.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"

namespace impactbench::compare {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> sweep(const std::string& engine, bool quick) {
  if (engine == engine_name::kEvent)
    return quick ? std::vector<double>{1e-4, 1e-8, 1e-12}
                 : std::vector<double>{1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
  return quick ? std::vector<double>{4e-3, 1e-3, 2.5e-4}
               : std::vector<double>{8e-3, 4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4};
}

}  // namespace

std::vector<WorkPoint> work_precision(const scenario::Scenario& s, const std::string& error_name,
                                      bool quick,
                                      const std::function<void(const std::string&)>& note) {
  std::vector<WorkPoint> points;
  for (const auto& info : adapters::engine_registry()) {
    if (!info.run || !s.supports_engine(info.name)) continue;
    const bool tolerance_knob = info.name == engine_name::kEvent;
    for (const double value : sweep(info.name, quick)) {
      engines::SettingsRequest request;
      (tolerance_knob ? request.tolerance : request.dt) = value;
      WorkPoint point{info.name, tolerance_knob ? "tol" : "dt", value, kNaN, kNaN, ""};
      try {
        const auto run = info.run(s, engines::resolve_run_options(info.name, s, request));
        for (const auto& [name, v] : analytic_errors(s, run))
          if (name == error_name) point.error = std::abs(v);
        if (std::isnan(point.error))
          point.failure = "no " + error_name + " (the run lacks the feature)";
        else
          point.engine_cpu_seconds = run.engine_cpu_seconds;
      } catch (const std::exception& e) {
        point.failure = std::string("run failed: ") + e.what();
      }
      if (!point.failure.empty())
        note(info.name + " at " + point.setting + " " + output::number_text(value) + ": " +
             point.failure);
      points.push_back(std::move(point));
    }
  }
  return points;
}

}  // namespace impactbench::compare
