#include "lib/engines/event_driven/event_driven_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/engines/event_driven/contact_modes.hpp"
#include "lib/engines/event_driven/flow_session.hpp"
#include "lib/engines/event_driven/guard_set.hpp"
#include "lib/engines/event_driven/instant_processing.hpp"
#include "lib/engines/event_driven/run_context.hpp"
#include "lib/engines/event_driven/run_record.hpp"
#include "lib/engines/event_driven/sampler.hpp"
#include "lib/engines/event_driven/segment_flow.hpp"
#include "lib/engines/run_timer.hpp"
#include "lib/output/message_text.hpp"

namespace impactbench::engines::event_driven {
namespace {

// The one line a run stopped by max_steps_between_samples ends with: where, and what to change.
std::string too_much_work_message(double t, long steps) {
  return "event-driven: the flow integrator's steps have collapsed at t = " +
         output::number_text(t) + " s (" + std::to_string(steps) +
         " steps without reaching the next output sample): the flow is too stiff for the "
         "method; run it with --option method=bdf";
}

void validate(const EventDrivenOptions& o) {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("event-driven options: " + what);
  };
  if (!(o.relative_tolerance > 0.0) || !(o.absolute_tolerance > 0.0))
    fail("relative_tolerance and absolute_tolerance must be > 0");
  if (!(o.output_interval >= 0.0)) fail("output_interval must be >= 0");
  if (o.max_events <= 0) fail("max_events must be > 0");
  if (o.max_events_per_instant <= 0) fail("max_events_per_instant must be > 0");
  if (o.max_steps_between_samples <= 0) fail("max_steps_between_samples must be > 0");
  if (!(o.contact_margin > 0.0)) fail("contact_margin must be > 0");
  if (!(o.gap_tolerance > 0.0) || !(o.velocity_tolerance > 0.0) ||
      !(o.complementarity_tolerance > 0.0))
    fail("gap, velocity and complementarity tolerances must be > 0");
  if (o.zeno_impact_count <= 0) fail("zeno_impact_count must be > 0");
  if (!(o.zeno_velocity >= 0.0) || !(o.zeno_min_interval >= 0.0))
    fail("zeno_velocity and zeno_min_interval must be >= 0");
  if (!(o.max_step >= 0.0)) fail("max_step must be >= 0");
  if (!(o.initial_step >= 0.0)) fail("initial_step must be >= 0");
  if (!(o.startup_step_growth > 1.0)) fail("startup_step_growth must be > 1");
  if (o.startup_order < 0) fail("startup_order must be >= 0");
  if (!(o.nonlinear_convergence_coefficient > 0.0))
    fail("nonlinear_convergence_coefficient must be > 0");
  if (!(o.flow_rank_threshold > 0.0) || !(o.flow_residual_tolerance > 0.0) ||
      !(o.friction_capacity_floor > 0.0) || !(o.stick_impulse_residual > 0.0))
    fail(
        "flow_rank_threshold, flow_residual_tolerance, friction_capacity_floor and "
        "stick_impulse_residual must be > 0");
}

// One simulate() call: the hybrid state, the segments between events and the output.
class Run {
 public:
  Run(const model::LagrangianSystem<double>& system, const EventDrivenOptions& options,
      const EventDrivenIntegrator::Input& input, const EventDrivenIntegrator::Observer& observer,
      EventDrivenResult& result)
      : run_(system, options, input),
        result_(result),
        sampler_(run_, observer, result.samples, timer_),
        flow_(run_, modes_),
        guards_(run_, modes_, flow_),
        instants_(run_, modes_, sampler_, result) {}

  void execute(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double duration);

 private:
  enum class StepEnd { kContinue, kNewSegment, kStop };
  bool integrate_segment(FlowSession& session, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v);
  void begin_segment(FlowSession& session, double t, const Eigen::VectorXd& q,
                     const Eigen::VectorXd& v, Eigen::VectorXd& y);
  StepEnd step(FlowSession& session, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v,
               Eigen::VectorXd& y);
  void finish(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, bool alive);

  RunContext run_;
  EventDrivenResult& result_;
  RunTimer timer_;  // the observer's samples are recording, the rest integration
  ContactModes modes_;
  Sampler sampler_;
  SegmentFlow flow_;
  GuardSet guards_;
  InstantProcessor instants_;
  std::vector<model::Contact<double>> contacts_;  // a segment's first contacts (storage kept)
};

void Run::execute(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double duration) {
  timer_.start(RunTimer::Phase::kEngine);
  Eigen::VectorXd q = q0, v = v0;
  double t = 0.0;
  const std::unique_ptr<FlowSession> session = make_flow_session(
      run_.nq + run_.nv, run_.options,
      [this](double tt, const Eigen::Ref<const Eigen::VectorXd>& y,
             Eigen::Ref<Eigen::VectorXd> yd) { flow_.rhs(tt, y, yd); },
      [this](double tt, const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> g) {
        guards_.evaluate(tt, y, g);
      });
  sampler_.start(q, v, duration);
  try {
    bool alive = instants_.process(t, q, v, {}, /*initial=*/true);
    if (alive && run_.options.sample_events && !result_.events.empty()) sampler_.emit(t, q, v);
    while (alive && t < duration) alive = integrate_segment(*session, t, q, v);
    finish(t, q, v, alive);
  } catch (...) {
    sampler_.flush();  // the observer still gets the samples before the error
    throw;
  }
}

// One segment: from (t, q, v) until an event instant has been processed, the tracked contacts
// must change, the end is reached or the run fails (false).
bool Run::integrate_segment(FlowSession& session, double& t, Eigen::VectorXd& q,
                            Eigen::VectorXd& v) {
  Eigen::VectorXd y(run_.nq + run_.nv);
  begin_segment(session, t, q, v, y);
  StepEnd end = StepEnd::kContinue;
  while (end == StepEnd::kContinue) end = step(session, t, q, v, y);
  result_.summary.rhs_evaluations += session.rhs_evaluations();
  result_.summary.root_evaluations += session.root_evaluations();
  result_.summary.steps += session.steps();
  return end != StepEnd::kStop;
}

void Run::begin_segment(FlowSession& session, double t, const Eigen::VectorXd& q,
                        const Eigen::VectorXd& v, Eigen::VectorXd& y) {
  run_.find_contacts(q, v, contacts_);
  guards_.begin_segment(contacts_);
  y << q, v;
  session.restart(t, y, guards_.num_roots(), sampler_.t_end());
  flow_.begin_segment();
  guards_.check(t, y);  // arms the guards clear of zero
  ++result_.summary.segments;
  result_.summary.max_tracked_contacts =
      std::max(result_.summary.max_tracked_contacts, static_cast<long>(guards_.num_slots()));
}

// One integrator step (or root) and what it ends in.
Run::StepEnd Run::step(FlowSession& session, double& t, Eigen::VectorXd& q, Eigen::VectorXd& v,
                       Eigen::VectorXd& y) {
  const auto outcome = session.step();
  // Close roots after a root of an unarmed guard: restart at that root (t, q, v), where the
  // library sets a guard stuck at zero aside; at the restart's own time it would recur.
  if (outcome == FlowSession::StepOutcome::kCloseRoots && t > session.restart_time())
    return StepEnd::kNewSegment;
  if (outcome == FlowSession::StepOutcome::kFailure ||
      outcome == FlowSession::StepOutcome::kCloseRoots) {
    const bool singular = flow_.failed();
    record_failure(
        result_,
        singular ? SimulationStatus::kSingularDynamics : SimulationStatus::kIntegratorFailure,
        session.failure_message() + " at t = " + output::number_text(session.time()) +
            (singular ? " s (constrained dynamics without solution)" : " s"));
    return StepEnd::kStop;
  }
  t = session.time();
  sampler_.emit_until(t, session);
  if (!sampler_.count_step()) {
    record_failure(result_, SimulationStatus::kIntegratorFailure,
                   too_much_work_message(t, run_.options.max_steps_between_samples));
    return StepEnd::kStop;
  }
  y = session.state();
  q = y.head(run_.nq);
  v = y.tail(run_.nv);
  if (outcome == FlowSession::StepOutcome::kReachedEnd || t >= sampler_.t_end())
    return StepEnd::kNewSegment;
  FiredGuards fired;
  if (outcome == FlowSession::StepOutcome::kRoot) {
    const std::vector<int> roots = session.roots_found();
    fired = guards_.fired_by(roots);
    // None: an untracked pair came within half the margin (track it from here), or a root of
    // an unarmed guard's round-off.
    if (fired.empty())
      return guards_.approach_fired(roots) ? StepEnd::kNewSegment : StepEnd::kContinue;
    guards_.add_guards_at_zero(t, y, fired);
  } else {
    fired = guards_.check(t, y);
    if (fired.empty() && guards_.all_armed()) session.guards_armed();
    if (fired.empty()) {
      // A contact entering the tracking margin needs its own root functions (the approach
      // guard normally restarts first); one that left keeps its slot.
      return guards_.tracks_all_checked() ? StepEnd::kContinue : StepEnd::kNewSegment;
    }
  }
  if (!instants_.process(t, q, v, fired, /*initial=*/false)) return StepEnd::kStop;
  if (run_.options.sample_events) sampler_.emit(t, q, v);
  return StepEnd::kNewSegment;
}

void Run::finish(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, bool alive) {
  if (alive)
    sampler_.finish(q, v);
  else
    sampler_.flush();  // the samples up to the failure
  result_.final_time = t;
  result_.q = run_.normalized_positions(q);
  result_.v = v;
  timer_.stop();
  result_.summary.engine_cpu_seconds = timer_.engine_cpu_seconds();
  result_.summary.record_cpu_seconds = timer_.record_cpu_seconds();
  result_.summary.wall_seconds = timer_.wall_seconds();
}

}  // namespace

EventDrivenIntegrator::EventDrivenIntegrator(const model::LagrangianSystem<double>& system,
                                             EventDrivenOptions options)
    : system_(system), options_(std::move(options)) {
  validate(options_);
}

EventDrivenResult EventDrivenIntegrator::simulate(const Eigen::VectorXd& q0,
                                                  const Eigen::VectorXd& v0, const Input& input,
                                                  double duration, const Observer& observer) const {
  if (q0.size() != system_.num_positions() || v0.size() != system_.num_velocities())
    throw std::invalid_argument("event-driven: initial state has sizes (" +
                                std::to_string(q0.size()) + ", " + std::to_string(v0.size()) +
                                "), the system needs (" + std::to_string(system_.num_positions()) +
                                ", " + std::to_string(system_.num_velocities()) + ")");
  if (!q0.allFinite() || !v0.allFinite())
    throw std::invalid_argument("event-driven: initial state is not finite");
  if (!(duration > 0.0) || !std::isfinite(duration))
    throw std::invalid_argument("event-driven: duration must be a finite positive time");
  EventDrivenResult result;
  Run run(system_, options_, input, observer, result);
  run.execute(q0, v0, duration);
  return result;
}

}  // namespace impactbench::engines::event_driven
