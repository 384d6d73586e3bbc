#pragma once
// The number of fixed steps (or output samples) of a run, checked before the run starts, so that
// a count that overflows a long (or one no run could finish) is refused up front and never
// silently turned into zero steps. Steps are not kept in memory unless asked for
// (RecordingOptions): what is kept is bounded by kMaxKeptRecords, not by this.
#include <string>

namespace impactbench::engines {

/// Largest number of steps or samples a run may have: 1e12 steps of a microsecond each take
/// twelve days, and every step index and time k · step stays exact in a double.
inline constexpr double kMaxSteps = 1e12;

/// ceil(duration / step), with the last step shortened to end at `duration`. Throws
/// std::invalid_argument naming `engine`, both values, the count and the limit when the count
/// exceeds kMaxSteps, and when duration or step is not finite and positive. `step_name` says
/// what the step is ("step" or "output_interval").
long checked_step_count(const std::string& engine, double duration, double step,
                        const std::string& step_name = "step");

/// The whole steps a fixed-step reference engine takes, round(duration / step), after
/// checked_step_count has refused what cannot fit (same exceptions).
long fixed_step_count(const std::string& engine, double duration, double step);

}  // namespace impactbench::engines
