#include "lib/engines/event_driven/cvode_session.hpp"

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "lib/engines/event_driven/root_search.hpp"

namespace impactbench::engines::event_driven {
namespace {

Eigen::Map<Eigen::VectorXd> view(N_Vector v) {
  return {N_VGetArrayPointer_Serial(v), static_cast<Eigen::Index>(N_VGetLength_Serial(v))};
}

void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string("CVODE setup failed in ") + what);
}

}  // namespace

struct CvodeSession::Impl {
  struct ContextDeleter {
    void operator()(SUNContext ctx) const { SUNContext_Free(&ctx); }
  };
  struct VectorDeleter {
    void operator()(_generic_N_Vector* v) const { N_VDestroy(v); }
  };
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

  Rhs rhs;
  Roots roots;
  int size = 0;
  int num_roots = 0;
  double initial_step = 0.0;
  double startup_step_growth = 4.0;
  int startup_order = 0;
  bool startup_done = true;  // the startup growth limit is lifted (until the next restart)
  // Root location (root_search.hpp) on CVODE's dense output: the guards at the last time
  // returned (t_lo), and the end of the current CVODE step while roots inside it are returned.
  bool own_root_search = false;  // else CVODE's rootfinding
  bool have_g_lo = false;
  double t_lo = 0.0;
  Eigen::VectorXd g_lo, g_end, y_end;
  bool step_pending = false;  // the current step's end is not returned yet
  double t_end_of_step = 0.0;
  StepOutcome outcome_at_end = StepOutcome::kStep;
  std::vector<int> found;
  long root_evaluations = 0;
  std::string root_error;
  // Declaration order = reverse destruction order: CVODE memory first, the context last.
  std::unique_ptr<_SUNContext, ContextDeleter> context;
  std::unique_ptr<_generic_N_Vector, VectorDeleter> y;
  std::unique_ptr<_generic_N_Vector, VectorDeleter> dense;
  std::unique_ptr<_generic_N_Vector, VectorDeleter> probe;  // y at root-search times
  std::unique_ptr<_generic_SUNMatrix, MatrixDeleter> matrix;
  std::unique_ptr<_generic_SUNLinearSolver, SolverDeleter> solver;
  std::unique_ptr<_generic_SUNNonlinearSolver, NonlinearSolverDeleter> fixed_point;
  std::unique_ptr<void, MemoryDeleter> memory;

  // A guard that throws stops the integration (CVODE returns CV_RTFUNC_FAIL) with its message.
  static int root_callback(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
    auto* self = static_cast<Impl*>(user);
    Eigen::Map<Eigen::VectorXd> out(g, self->num_roots);
    return self->evaluate_roots(t, y, out) ? 0 : -1;
  }
  static int rhs_callback(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      auto out = view(ydot);
      self->rhs(t, view(y), out);
      return out.allFinite() ? 0 : 1;  // recoverable: CVODE retries with a smaller step
    } catch (const std::exception& error) {
      self->rhs_error = error.what();  // the cause, reported instead of CVODE's summary
      return -1;
    } catch (...) {
      return -1;
    }
  }
  // CVODE reports errors through this instead of printing them; the message ends up in the
  // run's status message.
  static void error_callback(int, const char* module, const char* function, char* message,
                             void* user) {
    auto* self = static_cast<Impl*>(user);
    self->last_error = std::string(module) + "/" + function + ": " + message;
  }
  std::string last_error;
  std::string rhs_error;
  // g(t, y) into out; false (with root_error set) when the guards threw.
  bool evaluate_roots(double t, N_Vector state, Eigen::Ref<Eigen::VectorXd> out) {
    ++root_evaluations;
    try {
      roots(t, view(state), out);
      return true;
    } catch (const std::exception& error) {
      root_error = error.what();
    } catch (...) {
      root_error = "unknown error";
    }
    return false;
  }
};

CvodeSession::CvodeSession(int size, const EventDrivenOptions& options, Rhs rhs, Roots roots)
    : impl_(std::make_unique<Impl>()) {
  if (options.relative_tolerance <= 0.0 || options.absolute_tolerance <= 0.0)
    throw std::invalid_argument("event-driven: tolerances must be positive");
  impl_->rhs = std::move(rhs);
  impl_->roots = std::move(roots);
  impl_->size = size;
  impl_->initial_step = options.initial_step;
  impl_->startup_step_growth = options.startup_step_growth;
  impl_->startup_order = options.startup_order;
  impl_->own_root_search = options.dense_output_root_search;
  SUNContext ctx = nullptr;
  check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
  impl_->context.reset(ctx);
  impl_->y.reset(N_VNew_Serial(size, ctx));
  impl_->dense.reset(N_VNew_Serial(size, ctx));
  impl_->probe.reset(N_VNew_Serial(size, ctx));
  const bool adams = options.method == MultistepMethod::kAdams;
  impl_->memory.reset(CVodeCreate(adams ? CV_ADAMS : CV_BDF, ctx));
  if (adams) {
    impl_->fixed_point.reset(SUNNonlinSol_FixedPoint(impl_->y.get(), 0, ctx));
  } else {
    impl_->matrix.reset(SUNDenseMatrix(size, size, ctx));
    impl_->solver.reset(SUNLinSol_Dense(impl_->y.get(), impl_->matrix.get(), ctx));
  }
  if (!impl_->y || !impl_->dense || !impl_->probe || !impl_->memory ||
      (adams ? !impl_->fixed_point : (!impl_->matrix || !impl_->solver)))
    throw std::runtime_error("CVODE: allocation failed");
  void* mem = impl_->memory.get();
  N_VConst(0.0, impl_->y.get());
  check(CVodeInit(mem, &Impl::rhs_callback, 0.0, impl_->y.get()), "CVodeInit");
  check(CVodeSStolerances(mem, options.relative_tolerance, options.absolute_tolerance),
        "CVodeSStolerances");
  check(CVodeSetUserData(mem, impl_.get()), "CVodeSetUserData");
  check(CVodeSetErrHandlerFn(mem, &Impl::error_callback, impl_.get()), "CVodeSetErrHandlerFn");
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

void CvodeSession::restart(double t0, const Eigen::VectorXd& y0, int num_roots, double t_end) {
  void* mem = impl_->memory.get();
  view(impl_->y.get()) = y0;
  check(CVodeReInit(mem, t0, impl_->y.get()), "CVodeReInit");
  if (impl_->startup_order > 0) {
    check(CVodeSetEtaMaxEarlyStep(mem, impl_->startup_step_growth), "CVodeSetEtaMaxEarlyStep");
    impl_->startup_done = false;
  }
  impl_->num_roots = num_roots;
  impl_->have_g_lo = false;
  impl_->step_pending = false;
  impl_->root_evaluations = 0;
  impl_->found.assign(static_cast<std::size_t>(num_roots), 0);
  if (!impl_->own_root_search) {
    check(CVodeRootInit(mem, num_roots, num_roots > 0 ? &Impl::root_callback : nullptr),
          "CVodeRootInit");
    if (num_roots > 0) {
      std::vector<int> directions(static_cast<std::size_t>(num_roots), -1);
      check(CVodeSetRootDirection(mem, directions.data()), "CVodeSetRootDirection");
    }
  }
  check(CVodeSetStopTime(mem, t_end), "CVodeSetStopTime");
  if (impl_->initial_step > 0.0)
    check(CVodeSetInitStep(mem, impl_->initial_step), "CVodeSetInitStep");
  t_ = t0;
}

CvodeSession::StepOutcome CvodeSession::step() {
  Impl& s = *impl_;
  if (s.num_roots == 0 || !s.own_root_search) return cvode_step();
  const auto guard_failure = [&] {
    failure_ = root_failure_message();
    return StepOutcome::kFailure;
  };
  if (!s.have_g_lo) {
    s.g_lo.resize(s.num_roots);
    if (!s.evaluate_roots(t_, s.y.get(), s.g_lo)) return guard_failure();
    s.t_lo = t_;
    s.have_g_lo = true;
  }
  if (!s.step_pending) {
    const StepOutcome outcome = cvode_step();
    if (outcome == StepOutcome::kFailure) return outcome;
    s.g_end.resize(s.num_roots);
    if (!s.evaluate_roots(t_, s.y.get(), s.g_end)) return guard_failure();
    s.y_end = view(s.y.get());
    s.t_end_of_step = t_;
    s.outcome_at_end = outcome;
    s.step_pending = true;
  }
  bool crossing = false;
  for (Eigen::Index i = 0; i < s.num_roots; ++i)
    crossing = crossing || crosses_downwards(s.g_lo[i], s.g_end[i]);
  if (crossing) {
    double last_step = 0.0;
    CVodeGetLastStep(s.memory.get(), &last_step);
    // CVODE's root tolerance: 100 units of round-off of the step's end time and size.
    const double tolerance =
        100.0 * DBL_EPSILON * (std::abs(s.t_end_of_step) + std::abs(last_step));
    bool ok = true;
    const auto guards_at = [&](double t, Eigen::Ref<Eigen::VectorXd> out) {
      if (!ok) {  // after a failure: end the search
        out.setZero();
        return;
      }
      if (CVodeGetDky(s.memory.get(), t, 0, s.probe.get()) < 0)
        throw std::logic_error("CVodeGetDky outside the last step");
      ok = s.evaluate_roots(t, s.probe.get(), out);
    };
    RootBracket root =
        locate_earliest_root(guards_at, s.t_lo, s.g_lo, s.t_end_of_step, s.g_end, tolerance);
    if (!ok) return guard_failure();
    // The state returned is the dense output at the root, as CVODE's own root return.
    t_ = root.t_hi;
    if (CVodeGetDky(s.memory.get(), t_, 0, s.y.get()) < 0)
      throw std::logic_error("CVodeGetDky outside the last step");
    s.t_lo = t_;
    s.g_lo = std::move(root.g_hi);
    s.found = std::move(root.found);
    return StepOutcome::kRoot;
  }
  s.step_pending = false;
  t_ = s.t_end_of_step;
  view(s.y.get()) = s.y_end;
  s.t_lo = t_;
  std::swap(s.g_lo, s.g_end);
  return s.outcome_at_end;
}

CvodeSession::StepOutcome CvodeSession::cvode_step() {
  sunrealtype t_out = t_;
  const int flag = CVode(impl_->memory.get(), t_ + 1.0, impl_->y.get(), &t_out, CV_ONE_STEP);
  t_ = t_out;
  // The fixed-point corrector takes a failed right-hand side for a convergence failure and
  // retries with ever shorter steps: an exception in it (a cause no step size cures) ends
  // the run here, as Newton's CV_RHSFUNC_FAIL does.
  if (!impl_->rhs_error.empty() && flag >= 0) {
    failure_ = "CVODE right-hand side failed (" + impl_->rhs_error + ")";
    return StepOutcome::kFailure;
  }
  if (flag >= 0 && !impl_->startup_done) lift_startup_limit();
  if (flag == CV_ROOT_RETURN) return StepOutcome::kRoot;
  if (flag == CV_TSTOP_RETURN) return StepOutcome::kReachedEnd;
  if (flag < 0) {
    char* name = CVodeGetReturnFlagName(flag);  // malloc'ed by SUNDIALS
    failure_ = std::string("CVODE ") + (name ? name : "failure");
    std::free(name);
    if (flag == CV_RTFUNC_FAIL && !impl_->root_error.empty())
      failure_ = root_failure_message();
    else if (!impl_->rhs_error.empty())
      failure_ += " (" + impl_->rhs_error + ")";
    else if (!impl_->last_error.empty())
      failure_ += " (" + impl_->last_error + ")";
    return StepOutcome::kFailure;
  }
  return StepOutcome::kStep;
}

std::string CvodeSession::root_failure_message() const {
  return "CVODE CV_RTFUNC_FAIL (root function failed: " + impl_->root_error + ")";
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

Eigen::Map<const Eigen::VectorXd> CvodeSession::state() const {
  return {N_VGetArrayPointer_Serial(impl_->y.get()), impl_->size};
}

Eigen::Map<const Eigen::VectorXd> CvodeSession::interpolate(double t) const {
  const int flag = CVodeGetDky(impl_->memory.get(), t, 0, impl_->dense.get());
  if (flag < 0) throw std::logic_error("CVodeGetDky outside the last step");
  return {N_VGetArrayPointer_Serial(impl_->dense.get()), impl_->size};
}

std::vector<int> CvodeSession::roots_found() const {
  if (impl_->own_root_search) return impl_->found;
  std::vector<int> found(static_cast<std::size_t>(impl_->num_roots), 0);
  if (impl_->num_roots > 0) CVodeGetRootInfo(impl_->memory.get(), found.data());
  return found;
}

long CvodeSession::rhs_evaluations() const {
  long n = 0;
  CVodeGetNumRhsEvals(impl_->memory.get(), &n);
  return n;
}

long CvodeSession::root_evaluations() const {
  if (impl_->own_root_search) return impl_->root_evaluations;
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
