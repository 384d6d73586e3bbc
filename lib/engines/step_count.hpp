#pragma once
// The number of fixed steps (or output samples) of a run, checked before the run starts: every
// engine keeps each step's record in memory, so a count that cannot fit is refused up front
// instead of ending in std::bad_alloc hours later, and a count that overflows a long is never
// silently turned into zero steps.
#include <string>

namespace impactbench::engines {

/// Largest number of steps or samples a run may have.
inline constexpr double kMaxSteps = 1e7;

/// ceil(duration / step), with the last step shortened to end at `duration`. Throws
/// std::invalid_argument naming `engine`, both values, the count and the limit when the count
/// exceeds kMaxSteps, and when duration or step is not finite and positive. `step_name` says
/// what the step is ("step" or "output_interval").
long checked_step_count(const std::string& engine, double duration, double step,
                        const std::string& step_name = "step");

}  // namespace impactbench::engines
