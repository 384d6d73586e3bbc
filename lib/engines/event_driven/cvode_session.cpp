#include "lib/engines/event_driven/cvode_session.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <cvode/cvode.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

namespace impactbench::engines::event_driven {
namespace {

void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string("CVODE setup failed in ") + what);
}

}  // namespace

struct CvodeSession::Impl {
  struct MatrixDeleter {
    void operator()(_generic_SUNMatrix* m) const { SUNMatDestroy(m); }
  };
  struct SolverDeleter {
    void operator()(_generic_SUNLinearSolver* s) const { SUNLinSolFree(s); }
  };
  struct NonlinearSolverDeleter {
    void operator()(_generic_SUNNonlinearSolver* s) const { SUNNonlinSolFree(s); }
  };
  struct MemoryDeleter {
    void operator()(void* mem) const { CVodeFree(&mem); }
  };

  double initial_step = 0.0;
  double startup_step_growth = 4.0;
  int startup_order = 0;
  bool startup_done = true;  // the startup growth limit is lifted (until the next restart)
  // Declaration order = reverse destruction order: CVODE memory first.
  std::unique_ptr<_generic_SUNMatrix, MatrixDeleter> matrix;
  std::unique_ptr<_generic_SUNLinearSolver, SolverDeleter> solver;
  std::unique_ptr<_generic_SUNNonlinearSolver, NonlinearSolverDeleter> fixed_point;
  std::unique_ptr<void, MemoryDeleter> memory;
};

CvodeSession::CvodeSession(int size, const EventDrivenOptions& options, Rhs rhs, Roots roots)
    : FlowSession(size, options, std::move(rhs), std::move(roots), "CVODE", "CV_RTFUNC_FAIL"),
      impl_(std::make_unique<Impl>()) {
  impl_->initial_step = options.initial_step;
  impl_->startup_step_growth = options.startup_step_growth;
  impl_->startup_order = options.startup_order;
  const bool adams = options.method == FlowMethod::kAdams;
  impl_->memory.reset(CVodeCreate(adams ? CV_ADAMS : CV_BDF, context()));
  if (adams) {
    impl_->fixed_point.reset(SUNNonlinSol_FixedPoint(y(), 0, context()));
  } else {
    impl_->matrix.reset(SUNDenseMatrix(size, size, context()));
    impl_->solver.reset(SUNLinSol_Dense(y(), impl_->matrix.get(), context()));
  }
  if (!impl_->memory || (adams ? !impl_->fixed_point : (!impl_->matrix || !impl_->solver)))
    throw std::runtime_error("CVODE: allocation failed");
  void* mem = impl_->memory.get();
  check(CVodeInit(mem, &FlowCallbacks::rhs_callback, 0.0, y()), "CVodeInit");
  check(CVodeSStolerances(mem, options.relative_tolerance, options.absolute_tolerance),
        "CVodeSStolerances");
  check(CVodeSetUserData(mem, user_data()), "CVodeSetUserData");
  check(CVodeSetErrHandlerFn(mem, &FlowCallbacks::error_callback, user_data()),
        "CVodeSetErrHandlerFn");
  // Adams on the non-stiff flows between events: fixed-point corrector iterations, without the
  // dense (6N)² Jacobian by finite differences and its LU (N³ per setup on a row of N balls).
  // BDF, chosen for stiff springs and dampers, keeps Newton with the dense linear solver.
  if (adams)
    check(CVodeSetNonlinearSolver(mem, impl_->fixed_point.get()), "CVodeSetNonlinearSolver");
  else
    check(CVodeSetLinearSolver(mem, impl_->solver.get(), impl_->matrix.get()),
          "CVodeSetLinearSolver");
  check(CVodeSetMaxNumSteps(mem, 1000000), "CVodeSetMaxNumSteps");
  if (options.max_step > 0.0) check(CVodeSetMaxStep(mem, options.max_step), "CVodeSetMaxStep");
  check(CVodeSetNoInactiveRootWarn(mem), "CVodeSetNoInactiveRootWarn");
  // Every event restarts CVODE at order 1; letting the step grow slowly at first lets the
  // order rise before the local error reaches the tolerance (two orders of magnitude less
  // global error on a bouncing ball than CVODE's default first-step growth of 10⁴).
  check(CVodeSetEtaMaxFirstStep(mem, options.startup_step_growth), "CVodeSetEtaMaxFirstStep");
  check(CVodeSetEtaMaxEarlyStep(mem, options.startup_step_growth), "CVodeSetEtaMaxEarlyStep");
  // Solve the corrector equations well below the local error test, so that Newton's residual
  // (with a difference-quotient Jacobian) does not accumulate over many short segments.
  check(CVodeSetNonlinConvCoef(mem, options.nonlinear_convergence_coefficient),
        "CVodeSetNonlinConvCoef");
}

CvodeSession::~CvodeSession() = default;

void CvodeSession::restart_library(double t0, int num_roots, double t_end) {
  void* mem = impl_->memory.get();
  check(CVodeReInit(mem, t0, y()), "CVodeReInit");
  if (impl_->startup_order > 0) {
    check(CVodeSetEtaMaxEarlyStep(mem, impl_->startup_step_growth), "CVodeSetEtaMaxEarlyStep");
    impl_->startup_done = false;
  }
  if (!own_root_search()) {
    check(CVodeRootInit(mem, num_roots, num_roots > 0 ? &FlowCallbacks::root_callback : nullptr),
          "CVodeRootInit");
    if (num_roots > 0) {
      std::vector<int> directions(static_cast<std::size_t>(num_roots), -1);
      check(CVodeSetRootDirection(mem, directions.data()), "CVodeSetRootDirection");
    }
  }
  check(CVodeSetStopTime(mem, t_end), "CVodeSetStopTime");
  if (impl_->initial_step > 0.0)
    check(CVodeSetInitStep(mem, impl_->initial_step), "CVodeSetInitStep");
}

CvodeSession::StepOutcome CvodeSession::library_step() {
  sunrealtype t_out = t_;
  const int flag = CVode(impl_->memory.get(), t_ + 1.0, y(), &t_out, CV_ONE_STEP);
  t_ = t_out;
  // The fixed-point corrector takes a failed right-hand side for a convergence failure and
  // retries with ever shorter steps: an exception in it (a cause no step size cures) ends
  // the run here, as Newton's CV_RHSFUNC_FAIL does.
  if (!callbacks().rhs_error.empty() && flag >= 0) {
    failure_ = "CVODE right-hand side failed (" + callbacks().rhs_error + ")";
    return StepOutcome::kFailure;
  }
  if (flag >= 0 && !impl_->startup_done) lift_startup_limit();
  if (flag == CV_ROOT_RETURN) return StepOutcome::kRoot;
  if (flag == CV_TSTOP_RETURN) return StepOutcome::kReachedEnd;
  if (flag < 0) {
    char* name = CVodeGetReturnFlagName(flag);  // malloc'ed by SUNDIALS
    failure_ = failure_text(name ? name : "failure", flag == CV_RTFUNC_FAIL);
    std::free(name);
    illegal_input_ = flag == CV_ILL_INPUT;
    return StepOutcome::kFailure;
  }
  return StepOutcome::kStep;
}

void CvodeSession::lift_startup_limit() {
  // The slow startup growth protects the order-1 steps, whose local error grows like h²; from
  // order 2 on, CVODE's error estimate carries the history and the early steps may grow as
  // fast as its own first step would (a constant-force flight is then done in a few steps).
  int order = 0;
  CVodeGetCurrentOrder(impl_->memory.get(), &order);
  if (order < impl_->startup_order) return;
  CVodeSetEtaMaxEarlyStep(impl_->memory.get(), kGrowthAfterStartup);
  impl_->startup_done = true;
}

void CvodeSession::dense_output(double t, N_Vector out) const {
  if (CVodeGetDky(impl_->memory.get(), t, 0, out) < 0)
    throw std::logic_error("CVodeGetDky outside the last step");
}

double CvodeSession::last_step_size() const {
  double h = 0.0;
  CVodeGetLastStep(impl_->memory.get(), &h);
  return h;
}

void CvodeSession::library_roots_found(int* found) const {
  CVodeGetRootInfo(impl_->memory.get(), found);
}

long CvodeSession::rhs_evaluations() const {
  long n = 0;
  CVodeGetNumRhsEvals(impl_->memory.get(), &n);
  return n;
}

long CvodeSession::library_root_evaluations() const {
  long n = 0;
  CVodeGetNumGEvals(impl_->memory.get(), &n);
  return n;
}

long CvodeSession::steps() const {
  long n = 0;
  CVodeGetNumSteps(impl_->memory.get(), &n);
  return n;
}

}  // namespace impactbench::engines::event_driven
