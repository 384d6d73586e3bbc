#include "lib/engines/step_count.hpp"

#include <cmath>
#include <stdexcept>

#include "lib/output/message_text.hpp"

namespace impactbench::engines {

long checked_step_count(const std::string& engine, double duration, double step,
                        const std::string& step_name) {
  using output::number_text;
  if (!(std::isfinite(duration) && duration > 0.0))
    throw std::invalid_argument(engine + ": duration must be finite and > 0, got " +
                                number_text(duration));
  if (!(std::isfinite(step) && step > 0.0))
    throw std::invalid_argument(engine + ": " + step_name + " must be finite and > 0, got " +
                                number_text(step));
  // The 1e-9 keeps duration = n·step from gaining a last step of rounding size.
  const double count = std::ceil(duration / step - 1e-9);
  if (!(count <= kMaxSteps))
    throw std::invalid_argument(engine + ": duration " + number_text(duration) + " s at " +
                                step_name + " " + number_text(step) + " s needs " +
                                number_text(count) + " steps; at most " + number_text(kMaxSteps) +
                                " are allowed (use a larger step or a shorter duration)");
  return count < 1.0 ? 1L : static_cast<long>(count);
}

long fixed_step_count(const std::string& engine, double duration, double step) {
  checked_step_count(engine, duration, step);
  return static_cast<long>(std::llround(duration / step));
}

}  // namespace impactbench::engines
