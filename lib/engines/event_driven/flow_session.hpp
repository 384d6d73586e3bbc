#pragma once
// The integrator of the flow between events, behind one contract whichever library integrates:
// CVODE's multistep methods (cvode_session.hpp), ARKODE's explicit Runge–Kutta pairs
// (erk_session.hpp) or our own driver of the same pairs (own_erk_session.hpp), chosen once by
// EventDrivenOptions::method (make_flow_session).
//
// The integrator restarts the session at every event, with a new set of root functions, so one
// session serves a whole run. Roots are located by the library's rootfinding, or
// (EventDrivenOptions::dense_output_root_search) here on the library's dense output
// (root_search.hpp): same contract and tolerance, fewer evaluations of the guards per root.
// The session owns the SUNDIALS context and the state vectors; each library's memory is owned
// by its subclass.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/event_driven_options.hpp"
#include "lib/engines/event_driven/flow_callbacks.hpp"
#include "lib/engines/event_driven/sundials_handles.hpp"

namespace impactbench::engines::event_driven {

class FlowSession {
 public:
  using Rhs = FlowCallbacks::Rhs;
  using Roots = FlowCallbacks::Roots;

  /// kCloseRoots: the library refused to go on from a root because a root function was zero
  /// there and still zero just after it (CVODE's and ARKODE's "root found at and very near t"),
  /// e.g. the gap of an open contact that an impact left at exactly zero without moving it.
  /// The session then stays at the root; a restart there sets such a guard aside until it moves.
  enum class StepOutcome { kStep, kRoot, kReachedEnd, kFailure, kCloseRoots };

  virtual ~FlowSession();
  FlowSession(const FlowSession&) = delete;
  FlowSession& operator=(const FlowSession&) = delete;

  /// (Re)start at (t0, y0) with `num_roots` root functions, all detected only when decreasing
  /// through zero; integrate no further than t_end.
  void restart(double t0, const Eigen::VectorXd& y0, int num_roots, double t_end);
  /// One internal step, or the earliest root within it; `time()` and `state()` are then the
  /// step's end or the root. After a root the next call continues in the same step. kFailure
  /// ends the integration; failure_message() says why, with the message of the exception when
  /// the right-hand side or a guard threw.
  StepOutcome step();
  double time() const { return t_; }
  /// The time of the last restart.
  double restart_time() const { return restart_time_; }
  Eigen::Map<const Eigen::VectorXd> state() const;
  /// Dense output y(t) for t within the last step; the view is valid until the next call.
  Eigen::Map<const Eigen::VectorXd> interpolate(double t) const;
  /// Which root functions were found at the last kRoot (entries ±1, 0).
  std::vector<int> roots_found() const;
  const std::string& failure_message() const { return failure_; }
  /// Called by the integrator after a kStep once every guard has moved clear of zero since the
  /// restart (a guard that starts at zero counts a root only after that): from then on a
  /// one-step method may lengthen its steps at once (ErkSession); CVODE's startup ignores it.
  virtual void guards_armed() {}
  /// The work since the last restart.
  virtual long rhs_evaluations() const = 0;
  long root_evaluations() const;
  virtual long steps() const = 0;

 protected:
  /// `library` names the integrator in failure messages ("CVODE"), `root_failure_flag` its
  /// return flag when a guard fails ("CV_RTFUNC_FAIL").
  FlowSession(int size, const EventDrivenOptions& options, Rhs rhs, Roots roots,
              std::string library, std::string root_failure_flag);

  /// Restart the library at (t0, state vector y) with `num_roots` root functions of its own
  /// (0 when the roots are located here).
  virtual void restart_library(double t0, int num_roots, double t_end) = 0;
  /// One library step, without root location here: advances t_ and the state vector y, sets
  /// failure_ on kFailure.
  virtual StepOutcome library_step() = 0;
  /// y(t) from the dense output of the last step into out; throws std::logic_error outside it.
  virtual void dense_output(double t, N_Vector out) const = 0;
  virtual double last_step_size() const = 0;
  /// The library's root information and guard evaluations (its own rootfinding).
  virtual void library_roots_found(int* found) const = 0;
  virtual long library_root_evaluations() const = 0;
  /// The failure message for the library's return flag named `flag_name`; the message of a
  /// guard or right-hand side that threw, else the library's last error report, in brackets.
  std::string failure_text(const std::string& flag_name, bool root_function_failed) const;

  SUNContext context() const { return context_.get(); }
  N_Vector y() const { return y_.get(); }
  /// The user data of the library's callbacks.
  FlowCallbacks* user_data() { return &callbacks_; }
  const FlowCallbacks& callbacks() const { return callbacks_; }
  bool own_root_search() const { return own_root_search_; }

  double t_ = 0.0;
  std::string failure_;
  /// Set by library_step with a kFailure for the library's "illegal input" flag, which is how
  /// it reports close roots when it resumes after a root.
  bool illegal_input_ = false;

 private:
  /// The failure of a guard that threw, with the exception's message.
  std::string root_failure_message() const;
  /// step() with root location on the dense output.
  StepOutcome step_with_own_root_search();

  FlowCallbacks callbacks_;
  std::string library_;
  std::string root_failure_flag_;
  double restart_time_ = 0.0;
  bool after_root_ = false;  // the last step() returned kRoot
  int size_ = 0;
  bool own_root_search_ = false;  // else the library's rootfinding
  // Root location on the dense output: the guards at the last time returned (t_lo), and the
  // end of the current library step while roots inside it are returned.
  bool have_g_lo_ = false;
  double t_lo_ = 0.0;
  Eigen::VectorXd g_lo_, g_end_, y_end_;
  bool step_pending_ = false;  // the current step's end is not returned yet
  double t_end_of_step_ = 0.0;
  StepOutcome outcome_at_end_ = StepOutcome::kStep;
  std::vector<int> found_;
  // Declaration order = reverse destruction order: the vectors before the context.
  SunContextPtr context_;
  SunVectorPtr y_;
  SunVectorPtr dense_;
  SunVectorPtr probe_;  // y at root-search times
};

/// The session of options.method: CVODE for bdf and adams, ARKODE's ERKStep for erk, our own
/// driver of the same pairs for own_erk.
std::unique_ptr<FlowSession> make_flow_session(int size, const EventDrivenOptions& options,
                                               FlowSession::Rhs rhs, FlowSession::Roots roots);

}  // namespace impactbench::engines::event_driven
