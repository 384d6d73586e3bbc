#pragma once
// The flow session of `method = own_erk`: the explicit Runge–Kutta pair of
// EventDrivenOptions::erk_pair (ARKODE's coefficients, erk_table.hpp) stepped by our own driver
// instead of ARKODE's ERKStep. Same contract as ErkSession (flow_session.hpp), with the roots
// always located on the dense output (root_search.hpp). What it saves is the library's overhead
// per step on a small state: ERKStep spends about 17 k instructions on a step of the bouncing
// ball's six states besides the right-hand sides (vector operations through function tables,
// setup at every restart), this driver about 3 k.
//
// Error control: the embedded pair's difference, in SUNDIALS' weighted RMS norm (weights
// 1 / (rtol |y_i| + atol) at the step's start); a step is accepted when that norm is at most 1,
// and the next is h · min(10, max(0.2, 0.9 ‖err‖^(−1/(p̂+1)))) with p̂ the embedding's order
// (no growth right after a rejected step). Dense output: the cubic Hermite interpolant of y and
// ẏ at both ends of the step, as `method = erk` uses (exact for a flight under constant forces),
// and for Dormand–Prince 5(4) its continuous extension of order 4 on top, from the same stages
// (erk_table.hpp): event instants and samples between large steps as accurate as the steps.
// Startup after an event as ErkSession (carried_step.hpp): short steps from initial_step until
// the guards are armed, then the step carried over the event.
#include <memory>

#include "lib/engines/event_driven/carried_step.hpp"
#include "lib/engines/event_driven/flow_session.hpp"

namespace impactbench::engines::event_driven {

class OwnErkSession final : public FlowSession {
 public:
  OwnErkSession(int size, const EventDrivenOptions& options, Rhs rhs, Roots roots);
  ~OwnErkSession() override;

  void guards_armed() override;
  long rhs_evaluations() const override { return rhs_evaluations_; }
  long steps() const override { return steps_; }

 private:
  void restart_library(double t0, int num_roots, double t_end) override;
  StepOutcome library_step() override;
  void dense_output(double t, N_Vector out) const override;
  double last_step_size() const override { return h_last_; }
  void library_roots_found(int* found) const override;
  long library_root_evaluations() const override { return callbacks().root_evaluations; }

  /// ẏ at (t, y) into out, counted: FlowCallbacks::evaluate_rhs's flag, with failure_ set when
  /// the right-hand side threw.
  int evaluate(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
               Eigen::Ref<Eigen::VectorXd> out);
  /// The first step after a restart with initial_step = 0: h with h ‖ẏ‖ = 1 % of ‖y‖ in the
  /// error weights' norm (at least 1e-6 s), within the time left.
  double estimated_first_step() const;
  /// The dense output's four vectors of the step just taken, ending at y_new (dense_output).
  void prepare_dense_output(const Eigen::Ref<const Eigen::VectorXd>& y_new);
  /// The controller's factor on h for an error norm: 0.9 ‖err‖^(−1/(p̂+1)) within [0.2, 10].
  double step_factor(double error) const;
  /// The weighted RMS norm of v with the error weights of y.
  double error_norm(const Eigen::Ref<const Eigen::VectorXd>& v,
                    const Eigen::Ref<const Eigen::VectorXd>& y) const;

  struct Tableau;
  std::unique_ptr<const Tableau> tableau_;
  double relative_tolerance_, absolute_tolerance_, initial_step_, max_step_;
  double t_end_ = 0.0;
  double t_old_ = 0.0;   // start of the last step (its dense output's interval)
  double h_ = 0.0;       // the next step to try
  double h_last_ = 0.0;  // the last step taken
  CarriedStep carried_;
  bool have_f_ = false;               // f_ is ẏ at (t_, y)
  bool have_step_ = false;            // a step since the restart (dense output over [t_old_, t_])
  bool non_finite_rejected_ = false;  // the last rejected step met a right-hand side not finite
  long steps_ = 0, rhs_evaluations_ = 0;
  // ẏ at the last step's end, the step's start, the stage state, the embedded difference, the
  // stages of the last step, and its dense output's vectors (kept here: the session's state
  // vector is overwritten with the dense output at a root inside the step).
  Eigen::VectorXd f_, y_old_, stage_state_, error_;
  Eigen::MatrixXd k_, dense_;
};

}  // namespace impactbench::engines::event_driven
