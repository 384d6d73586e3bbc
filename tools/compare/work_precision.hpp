#pragma once
// Work-precision points: for each engine a sweep of its accuracy knob (step size for the
// time-steppers and the reference engines, tolerance for the event-driven integrator), each
// point the error of one closed-form quantity against the process CPU time of the engine's
// stepping (our recording excluded). The points run as a sweep (tools/cli/suite_work_precision),
// on every core; this layer holds what they are and how the suite asks for them.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"

namespace impactbench::compare {

struct WorkPoint {
  std::string engine;
  std::string setting;  ///< "dt" or "tol"
  double value = 0.0;
  double error = 0.0;  ///< |measured − analytical| of the chosen quantity
  double engine_cpu_seconds = 0.0;
  std::string failure;  ///< why the point has no error (run failed, feature missing); else empty
};

/// The knob an engine's points sweep: "tol" for the event-driven integrator, else "dt".
std::string work_precision_knob(const std::string& engine);

/// The knob's values, coarse to fine (three in the quick suite).
std::vector<double> work_precision_values(const std::string& knob, bool quick);

/// Runs the points of every engine `scenario` (a shipped scenario, its duration possibly
/// shortened) lists for the metric `quantity` of analytic_errors (e.g. apex_error), keeping its
/// files in `dir`. A point whose run fails or lacks the quantity is kept with its `failure`
/// (error and time NaN) and also reported through `note`.
using WorkPrecisionRunner = std::function<std::vector<WorkPoint>(
    const scenario::Scenario& scenario, const std::string& quantity, bool quick,
    const std::filesystem::path& dir, const std::function<void(const std::string&)>& note)>;

}  // namespace impactbench::compare
