#pragma once
// RAII ownership of the SUNDIALS 6 objects behind one CVODE integration: the SUNContext, the
// state vector, the dense matrix and linear solver, and the CVODE memory. The right-hand side
// is a std::function called through CVODE's user-data pointer.
//
// The integrator restarts CVODE at every event (CVodeReInit keeps the memory), with a new set
// of root functions, so one session serves a whole run. Roots are located by CVODE's rootfinding,
// or (EventDrivenOptions::dense_output_root_search) here on CVODE's dense output
// (root_search.hpp): same contract and tolerance, fewer evaluations of the guards per root.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/event_driven_options.hpp"

namespace impactbench::engines::event_driven {

class CvodeSession {
 public:
  /// ẏ = rhs(t, y); writes ẏ into its third argument.
  using Rhs = std::function<void(double, const Eigen::Ref<const Eigen::VectorXd>&,
                                 Eigen::Ref<Eigen::VectorXd>)>;
  /// g(t, y), size given at restart.
  using Roots = std::function<void(double, const Eigen::Ref<const Eigen::VectorXd>&,
                                   Eigen::Ref<Eigen::VectorXd>)>;

  enum class StepOutcome { kStep, kRoot, kReachedEnd, kFailure };

  CvodeSession(int size, const EventDrivenOptions& options, Rhs rhs, Roots roots);
  ~CvodeSession();
  CvodeSession(const CvodeSession&) = delete;
  CvodeSession& operator=(const CvodeSession&) = delete;

  /// (Re)start at (t0, y0) with `num_roots` root functions, all detected only when decreasing
  /// through zero; integrate no further than t_end.
  void restart(double t0, const Eigen::VectorXd& y0, int num_roots, double t_end);
  /// One internal step (CV_ONE_STEP), or the earliest root within it; `time()` and `state()`
  /// are then the step's end or the root. After a root the next call continues in the same step.
  /// kFailure ends the integration; failure_message() says why, with the message of the
  /// exception when the right-hand side or a guard threw.
  StepOutcome step();
  double time() const { return t_; }
  Eigen::Map<const Eigen::VectorXd> state() const;
  /// Dense output y(t) for t within the last step; the view is valid until the next call.
  Eigen::Map<const Eigen::VectorXd> interpolate(double t) const;
  /// Which root functions were found at the last kRoot (entries ±1, 0).
  std::vector<int> roots_found() const;
  const std::string& failure_message() const { return failure_; }
  long rhs_evaluations() const;
  long root_evaluations() const;
  long steps() const;

 private:
  /// Largest early-step growth once the startup order is reached (CVODE's default growth of
  /// its first step).
  static constexpr double kGrowthAfterStartup = 1e4;
  void lift_startup_limit();
  /// The failure of a guard that threw, with the exception's message.
  std::string root_failure_message() const;
  /// One CVODE step, without root location.
  StepOutcome cvode_step();

  struct Impl;
  std::unique_ptr<Impl> impl_;
  double t_ = 0.0;
  std::string failure_;
};

}  // namespace impactbench::engines::event_driven
