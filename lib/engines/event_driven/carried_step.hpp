#pragma once
// The step a one-step method (ErkSession, OwnErkSession) carries over an event. After a restart
// the first steps are short (from initial_step, as CVODE's), so that a guard starting at zero is
// armed before it can cross again; once the integrator says the guards are armed, the method
// goes on with the step it had before the event instead of growing again from the short first
// step (a factor of about 10 per step). A one-step method needs no history, so resuming with a
// new step is exact.
#include <algorithm>

namespace impactbench::engines::event_driven {

class CarriedStep {
 public:
  /// At a restart: carry the last step taken, or the controller's next if shorter (0 before
  /// the first step). The controller's next step alone can grow without bound: on a flow the
  /// pair integrates exactly (a flight under constant forces) the error estimate is round-off.
  void restart(double next_step, double last_step) {
    carried_ = std::min(next_step, last_step);
    startup_ = true;
    resume_pending_ = false;
  }
  /// Once the guards are armed (the first time after a restart): resume with the carried step
  /// if the controller's next is shorter. Resumed before the next step, so that the last step's
  /// dense output stays available until then.
  void guards_armed(double next_step) {
    if (!startup_) return;
    startup_ = false;
    resume_pending_ = carried_ > next_step;
  }
  /// True once, before the step that resumes with step().
  bool take_resume() {
    const bool resume = resume_pending_;
    resume_pending_ = false;
    return resume;
  }
  double step() const { return carried_; }

 private:
  double carried_ = 0.0;
  bool startup_ = false;         // since the restart, the guards have not all been armed
  bool resume_pending_ = false;  // resume with the carried step before the next step
};

}  // namespace impactbench::engines::event_driven
