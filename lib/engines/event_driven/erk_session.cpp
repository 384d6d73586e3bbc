#include "lib/engines/event_driven/erk_session.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <arkode/arkode_erkstep.h>

#include "lib/engines/event_driven/carried_step.hpp"
#include "lib/engines/event_driven/erk_table.hpp"

namespace impactbench::engines::event_driven {
namespace {

void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string("ARKODE setup failed in ") + what);
}

// The library's work counters.
struct Counters {
  long steps = 0, rhs = 0;
};

}  // namespace

struct ErkSession::Impl {
  struct MemoryDeleter {
    void operator()(void* mem) const { ERKStepFree(&mem); }
  };
  std::unique_ptr<void, MemoryDeleter> memory;
  double initial_step = 0.0;
  double t_end = 0.0;
  CarriedStep carried;
  Counters before_resume;  // the segment's work before resume_at_carried_step

  /// The library's counters since its last ERKStepReInit.
  Counters counters() const {
    Counters c;
    ERKStepGetNumSteps(memory.get(), &c.steps);
    ERKStepGetNumRhsEvals(memory.get(), &c.rhs);
    return c;
  }
};

ErkSession::ErkSession(int size, const EventDrivenOptions& options, Rhs rhs, Roots roots)
    : FlowSession(size, options, std::move(rhs), std::move(roots), "ARKODE", "ARK_RTFUNC_FAIL"),
      impl_(std::make_unique<Impl>()) {
  impl_->memory.reset(ERKStepCreate(&FlowCallbacks::rhs_callback, 0.0, y(), context()));
  if (!impl_->memory) throw std::runtime_error("ARKODE: allocation failed");
  impl_->initial_step = options.initial_step;
  void* mem = impl_->memory.get();
  check(ERKStepSetTableNum(mem, arkode_erk_table(options.erk_pair)), "ERKStepSetTableNum");
  check(ERKStepSStolerances(mem, options.relative_tolerance, options.absolute_tolerance),
        "ERKStepSStolerances");
  check(ERKStepSetUserData(mem, user_data()), "ERKStepSetUserData");
  check(ERKStepSetErrHandlerFn(mem, &FlowCallbacks::error_callback, user_data()),
        "ERKStepSetErrHandlerFn");
  // Cubic Hermite dense output (y and ẏ at both ends of the step): exact on a flight under
  // constant forces, and no right-hand sides beyond the step's own. Degrees 4 and 5 cost two
  // more right-hand sides at every step where roots or samples are interpolated (twice the
  // time per event on the bouncing ball) without making the ball's impacts more accurate.
  check(ERKStepSetInterpolantDegree(mem, 3), "ERKStepSetInterpolantDegree");
  check(ERKStepSetMaxNumSteps(mem, 1000000), "ERKStepSetMaxNumSteps");
  if (options.max_step > 0.0) check(ERKStepSetMaxStep(mem, options.max_step), "ERKStepSetMaxStep");
}

ErkSession::~ErkSession() = default;

void ErkSession::restart_library(double t0, int, double t_end) {
  void* mem = impl_->memory.get();
  // The step carried over the event (carried_step.hpp; ARKODE proposes each step up to 20 times
  // longer than the last).
  double next_step = 0.0, last_step = 0.0;
  ERKStepGetCurrentStep(mem, &next_step);
  ERKStepGetLastStep(mem, &last_step);
  impl_->carried.restart(next_step, last_step);
  check(ERKStepReInit(mem, &FlowCallbacks::rhs_callback, t0, y()), "ERKStepReInit");
  // A guard that starts the segment at zero is armed only once a step ends with it clear of
  // zero (guard_set.hpp), so the first steps are short (from initial_step), as CVODE's, until
  // the integrator says the guards are armed (guards_armed).
  check(ERKStepSetInitStep(mem, impl_->initial_step), "ERKStepSetInitStep");
  impl_->t_end = t_end;
  impl_->before_resume = {};
  init_roots(callbacks().num_roots);
}

void ErkSession::init_roots(int num_roots) {
  void* mem = impl_->memory.get();
  if (!own_root_search()) {
    check(ERKStepRootInit(mem, num_roots, num_roots > 0 ? &FlowCallbacks::root_callback : nullptr),
          "ERKStepRootInit");
    if (num_roots > 0) {
      std::vector<int> directions(static_cast<std::size_t>(num_roots), -1);
      check(ERKStepSetRootDirection(mem, directions.data()), "ERKStepSetRootDirection");
      // ARKODE keeps this in its root memory, which ERKStepRootInit creates.
      check(ERKStepSetNoInactiveRootWarn(mem), "ERKStepSetNoInactiveRootWarn");
    }
  }
  check(ERKStepSetStopTime(mem, impl_->t_end), "ERKStepSetStopTime");
}

ErkSession::StepOutcome ErkSession::library_step() {
  if (impl_->carried.take_resume()) resume_at_carried_step();
  sunrealtype t_out = t_;
  const int flag = ERKStepEvolve(impl_->memory.get(), t_ + 1.0, y(), &t_out, ARK_ONE_STEP);
  t_ = t_out;
  if (flag == ARK_ROOT_RETURN) return StepOutcome::kRoot;
  if (flag == ARK_TSTOP_RETURN) return StepOutcome::kReachedEnd;
  if (flag < 0) {
    char* name = ERKStepGetReturnFlagName(flag);  // malloc'ed by SUNDIALS
    failure_ = failure_text(name ? name : "failure", flag == ARK_RTFUNC_FAIL);
    std::free(name);
    // Repeated error-test failures of an explicit pair are nearly always stiffness (e.g. a
    // spatial slip starting from rest, docs/engines.md): say what handles it.
    if (flag == ARK_ERR_FAILURE)
      failure_ += "; the flow is too stiff for an explicit method: run it with --option method=bdf";
    illegal_input_ = flag == ARK_ILL_INPUT;
    return StepOutcome::kFailure;
  }
  return StepOutcome::kStep;
}

void ErkSession::guards_armed() {
  double next_step = 0.0;
  ERKStepGetCurrentStep(impl_->memory.get(), &next_step);
  impl_->carried.guards_armed(next_step);
}

void ErkSession::resume_at_carried_step() {
  // The restart is exact: the state is the last step's end (carried_step.hpp).
  void* mem = impl_->memory.get();
  Counters done = impl_->counters();
  done.steps += impl_->before_resume.steps;
  done.rhs += impl_->before_resume.rhs;
  check(ERKStepReInit(mem, &FlowCallbacks::rhs_callback, t_, y()), "ERKStepReInit");
  check(ERKStepSetInitStep(mem, impl_->carried.step()), "ERKStepSetInitStep");
  init_roots(callbacks().num_roots);
  impl_->before_resume = done;
}

void ErkSession::dense_output(double t, N_Vector out) const {
  if (ERKStepGetDky(impl_->memory.get(), t, 0, out) < 0)
    throw std::logic_error("ERKStepGetDky outside the last step");
}

double ErkSession::last_step_size() const {
  double h = 0.0;
  ERKStepGetLastStep(impl_->memory.get(), &h);
  return h;
}

void ErkSession::library_roots_found(int* found) const {
  ERKStepGetRootInfo(impl_->memory.get(), found);
}

long ErkSession::rhs_evaluations() const {
  return impl_->counters().rhs + impl_->before_resume.rhs;
}

long ErkSession::library_root_evaluations() const {
  return callbacks().root_evaluations;
}

long ErkSession::steps() const {
  return impl_->counters().steps + impl_->before_resume.steps;
}

}  // namespace impactbench::engines::event_driven
