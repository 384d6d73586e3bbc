#pragma once
// The flow session on ARKODE's ERKStep (EventDrivenOptions::method erk): an explicit
// Runge–Kutta pair (EventDrivenOptions::erk_pair) with error control and Hermite dense output,
// RAII ownership of the ARKODE memory. A one-step method needs no history: after an event it
// starts at full order, and once the guards are armed (a few short steps, as CVODE's) it goes
// on with the step size it had before the event instead of growing it again from the small
// first step.
#include <memory>

#include "lib/engines/event_driven/flow_session.hpp"

namespace impactbench::engines::event_driven {

class ErkSession final : public FlowSession {
 public:
  ErkSession(int size, const EventDrivenOptions& options, Rhs rhs, Roots roots);
  ~ErkSession() override;

  /// Goes on with the step size carried over the event, from the next step.
  void guards_armed() override;
  long rhs_evaluations() const override;
  long steps() const override;

 private:
  void restart_library(double t0, int num_roots, double t_end) override;
  /// The root functions (unless located here) and the stop time, after every ERKStepReInit.
  void init_roots(int num_roots);
  /// Restarts at the current step's end with the step size carried over the event.
  void resume_at_carried_step();
  StepOutcome library_step() override;
  void dense_output(double t, N_Vector out) const override;
  double last_step_size() const override;
  void library_roots_found(int* found) const override;
  long library_root_evaluations() const override;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace impactbench::engines::event_driven
