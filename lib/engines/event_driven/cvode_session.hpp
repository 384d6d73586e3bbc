#pragma once
// The flow session on CVODE (EventDrivenOptions::method bdf or adams): RAII ownership of the
// dense matrix and linear solver (BDF) or the fixed-point solver (Adams) and the CVODE memory.
// CVODE is restarted at every event (CVodeReInit keeps the memory) at order 1, with a small
// first step and a slow early step growth (event_driven_options.hpp).
#include <memory>

#include "lib/engines/event_driven/flow_session.hpp"

namespace impactbench::engines::event_driven {

class CvodeSession final : public FlowSession {
 public:
  CvodeSession(int size, const EventDrivenOptions& options, Rhs rhs, Roots roots);
  ~CvodeSession() override;

  long rhs_evaluations() const override;
  long steps() const override;

 private:
  /// Largest early-step growth once the startup order is reached (CVODE's default growth of
  /// its first step).
  static constexpr double kGrowthAfterStartup = 1e4;
  void lift_startup_limit();

  void restart_library(double t0, int num_roots, double t_end) override;
  StepOutcome library_step() override;
  void dense_output(double t, N_Vector out) const override;
  double last_step_size() const override;
  void library_roots_found(int* found) const override;
  long library_root_evaluations() const override;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace impactbench::engines::event_driven
