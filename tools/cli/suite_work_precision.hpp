#pragma once
// The suite's work-precision points, run as sweeps by the local executor (every core): for one
// scenario, a sweep file per knob (the step size of the time-steppers and reference engines, the
// tolerance of the event-driven integrator) is written into the suite's folder and run as
// `impactbench sweep` runs it; the points are read back from its results. Each folder can be
// rerun or extended by hand with `impactbench sweep DIR/spec.toml --out DIR`.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tools/compare/work_precision.hpp"

namespace impactbench::cli {

/// A compare::WorkPrecisionRunner. Clears `dir` first (a suite's figures come from this
/// program, never from an earlier build's results). Throws compare::ProcessInterrupted on
/// SIGINT/SIGTERM.
std::vector<compare::WorkPoint> work_precision_by_sweep(
    const scenario::Scenario& scenario, const std::string& quantity, bool quick,
    const std::filesystem::path& dir, const std::function<void(const std::string&)>& note);

}  // namespace impactbench::cli
