#pragma once
// The right-hand side and the guards of a flow session, called by CVODE or ARKODE through their
// user-data pointer (both take the same C signatures). An exception thrown in either is caught
// here and its message kept, so that the session can report the cause instead of the library's
// summary.
#include <functional>
#include <string>

#include <sundials/sundials_nvector.h>
#include <Eigen/Core>

namespace impactbench::engines::event_driven {

struct FlowCallbacks {
  /// ẏ = rhs(t, y); writes ẏ into its third argument.
  using Rhs = std::function<void(double, const Eigen::Ref<const Eigen::VectorXd>&,
                                 Eigen::Ref<Eigen::VectorXd>)>;
  /// g(t, y), size given at restart.
  using Roots = std::function<void(double, const Eigen::Ref<const Eigen::VectorXd>&,
                                   Eigen::Ref<Eigen::VectorXd>)>;

  Rhs rhs;
  Roots roots;
  int num_roots = 0;
  long root_evaluations = 0;  // by evaluate_roots, since the last restart
  std::string rhs_error;      // the message of an exception of the right-hand side
  std::string root_error;     // the message of an exception of the guards
  std::string last_error;     // the library's last error report

  /// ẏ = rhs(t, y) into out: 0, or 1 when ẏ is not finite (recoverable: a shorter step may
  /// avoid it), or −1 (with rhs_error set) when the right-hand side threw.
  int evaluate_rhs(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                   Eigen::Ref<Eigen::VectorXd> out);
  /// g(t, y) into out; false (with root_error set) when the guards threw.
  bool evaluate_roots(double t, N_Vector state, Eigen::Ref<Eigen::VectorXd> out);

  // The C callbacks; `user` is the FlowCallbacks.
  /// A non-finite ẏ is recoverable (the library retries with a smaller step); an exception is
  /// not.
  static int rhs_callback(double t, N_Vector y, N_Vector ydot, void* user);
  /// A guard that throws stops the integration (the library's root-function failure).
  static int root_callback(double t, N_Vector y, double* g, void* user);
  /// Keeps the library's error report instead of printing it.
  static void error_callback(int, const char* module, const char* function, char* message,
                             void* user);
};

}  // namespace impactbench::engines::event_driven
