#pragma once
// Work-precision points: for each engine a sweep of its accuracy knob (step size for the
// time-steppers and the reference engines, tolerance for the event-driven integrator), each
// point the error of one closed-form quantity against the process CPU time of the engine's
// stepping (our recording excluded).
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

/// Sweeps every available engine of the scenario; `error_name` is a metric of
/// analytic_errors() (e.g. apex_error). A point whose run fails or lacks the feature is kept
/// with its `failure` (error and time NaN) and also reported through `note`.
std::vector<WorkPoint> work_precision(const scenario::Scenario& scenario,
                                      const std::string& error_name, bool quick,
                                      const std::function<void(const std::string&)>& note);

}  // namespace impactbench::compare
