#include "tools/engines/moreau/moreau_engine.hpp"

#include <stdexcept>

#include "lib/engines/contact_events.hpp"
#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/engines/run_timer.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/output/message_text.hpp"
#include "lib/output/number_text.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/moreau/moreau_settings.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

const std::string kEngine = engine_name::kMoreau;

ContactSample contact_sample(const ContactImpulse& impulse) {
  ContactSample s;
  s.name = impulse.name;
  s.gap = impulse.gap;
  s.impulse_n = impulse.r_n;
  s.friction = impulse.friction;
  s.restitution = impulse.restitution;
  const auto d = impulse.r_t.size();
  s.impulse_t.head(d) = impulse.r_t;
  if (impulse.u_after.size() > 0) {
    s.velocity_n = impulse.u_after[0];
    s.velocity_t.head(d) = impulse.u_after.tail(d);
  }
  if (impulse.u_before.size() > 0) s.velocity_n_before = impulse.u_before[0];
  return s;
}

// The options the engine steps with: the observer reads each step's impulses from its report;
// nothing reads them afterwards.
MoreauJeanOptions engine_options(MoreauJeanOptions options) {
  options.record_impulses = false;
  return options;
}

}  // namespace

MoreauJeanOptions options_from(const RunOptions& run) {
  return engine_options(engine_options_of<MoreauJeanOptions>(run));
}

RunResult run_moreau_jean(const scenario::Scenario& scenario, const MoreauJeanOptions& settings,
                          const RunOptions& run) {
  const MoreauJeanOptions options = engine_options(settings);
  const BuiltSystem built = build_system(scenario);
  MoreauJeanStepper stepper(*built.system, options);
  const int nu = built.system->num_inputs();
  InputFunction input;
  if (nu > 0) {
    input = [&scenario, nu](double t) {
      return scenario.inputs.empty() ? Eigen::VectorXd(Eigen::VectorXd::Zero(nu))
                                     : scenario.input(t);
    };
  }

  RunResult out;
  out.engine = kEngine;
  out.recording = run.recording;
  out.trajectory.position_names = built.system->position_names();
  out.trajectory.velocity_names = built.system->velocity_names();
  ContactEvents events(options.impact);
  RunTimer timer;
  const auto observer = [&](const MoreauJeanState& state, const StepReport& report) {
    const auto recording = timer.scoped(RunTimer::Phase::kRecord);
    out.add_sample(state.t, state.q, state.v, built.system->energy(state.q, state.v));
    if (report.statistics.step_index == 0) return;
    StepRecord step;
    step.t = report.statistics.t;
    step.active_contacts = report.statistics.active_contacts;
    step.iterations = report.statistics.solver_iterations;
    step.residual = report.statistics.residual;
    step.solve_seconds = report.statistics.solve_seconds;
    step.converged = report.statistics.converged;
    std::vector<ClosedContact> closed;  // the contacts that carry an impulse
    for (const ContactImpulse& impulse : report.impulses()) {
      if (out.recording.keep_steps) step.contacts.push_back(contact_sample(impulse));
      if (impulse.r_n > 0.0)
        closed.push_back({impulse.name, -impulse.u_before[0], impulse.r_n,
                          impulse.r_t.size() == 1 ? impulse.r_t[0] : impulse.r_t.norm()});
    }
    events.after_step(step.t, closed, out.events);
    out.add_step(std::move(step));
  };

  const bool bare = run.recording.timing_only;  // no observer between the steps
  if (bare) out.add_sample(0.0, built.q0, built.v0, built.system->energy(built.q0, built.v0));
  timer.start(RunTimer::Phase::kEngine);
  const SimulationResult r =
      stepper.simulate(built.q0, built.v0, input, run.duration, bare ? Observer() : observer);
  timer.switch_to(RunTimer::Phase::kRecord);
  if (bare) {
    const MoreauJeanState& end = r.final_state;
    out.add_sample(end.t, end.q, end.v, r.summary.energy_end);
  }
  out.finish_recording();
  // The stepper's own: every contact the model finds within the contact margin (so every one
  // that touches or penetrates) at the start of every step and in the final state, the states a
  // recorded run samples; a PenetrationTracker would search them all again.
  out.max_penetration = r.summary.max_penetration;
  out.count_steps(/*has_tolerance=*/true);
  if (bare) {
    out.step_count = r.summary.steps;
    out.unconverged_steps = r.summary.solver_failures;
  }
  timer.stop();
  out.set_timing(timer);
  if (!r.succeeded())
    throw std::runtime_error("moreau: run stopped at t = " + output::number_text(r.final_state.t) +
                             " (" + to_string(r.status) + "): " + r.message);
  // Steps and unconverged steps are printed with every engine's run figures; these are the
  // stepper's own.
  out.summary = {{"max_active_contacts", std::to_string(r.summary.max_active_contacts)},
                 // Contacts found already penetrated that the candidate search had not seen
                 // coming (moreau_jean_stepper.hpp): each one is an impact taken late.
                 {"late_contacts", std::to_string(r.summary.late_contacts)},
                 {"worst_residual", output::number_text(r.summary.worst_residual)},
                 {"solver_iterations", std::to_string(r.summary.total_solver_iterations)}};
  return out;
}

}  // namespace impactbench::engines::moreau_jean
