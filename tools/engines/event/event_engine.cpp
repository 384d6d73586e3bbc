#include "tools/engines/event/event_engine.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/engines/run_timer.hpp"
#include "lib/engines/step_count.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/metrics/penetration.hpp"
#include "lib/output/number_text.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/event/event_settings.hpp"

namespace impactbench::engines::event_driven {
namespace {

// Closed contacts averaged over time: the modes after each event instant hold until the next.
double mean_closed_contacts(const EventDrivenResult& r) {
  if (!(r.final_time > 0.0)) return 0.0;
  double integral = 0.0;
  for (std::size_t i = 0; i < r.event_states.size(); ++i) {
    const double until = i + 1 < r.event_states.size() ? r.event_states[i + 1].t : r.final_time;
    integral += static_cast<double>(r.event_states[i].modes.size()) * (until - r.event_states[i].t);
  }
  return integral / r.final_time;
}

}  // namespace

EventDrivenOptions options_from(const RunOptions& run) {
  return engine_options_of<EventDrivenOptions>(run);
}

RunResult run_event_driven(const scenario::Scenario& scenario, const EventDrivenOptions& options,
                           const RunOptions& run) {
  const BuiltSystem built = build_system(scenario);
  const EventDrivenIntegrator integrator(*built.system, options);
  // A scenario without force inputs (e.g. the plank–box at rest) leaves u = 0.
  EventDrivenIntegrator::Input input;
  if (!scenario.inputs.empty()) input = [&scenario](double t) { return scenario.input(t); };
  if (options.output_interval > 0.0)
    checked_step_count(engine_name::kEvent, run.duration, options.output_interval,
                       "output_interval");
  RunResult out;
  out.engine = engine_name::kEvent;
  out.recording = run.recording;
  out.trajectory.position_names = built.system->position_names();
  out.trajectory.velocity_names = built.system->velocity_names();
  // Samples are recorded as the integrator emits them (its recording time).
  metrics::PenetrationTracker penetration(*built.system);
  const auto record = [&](const SampleView& s) {
    Eigen::VectorXd q = s.q, v = s.v;  // the recorded state's own vectors
    penetration.add(q, v);
    out.add_sample(s.t, std::move(q), std::move(v), s.energy);
  };
  const EventDrivenResult r = integrator.simulate(built.q0, built.v0, input, run.duration, record);
  if (!r.succeeded())
    throw std::runtime_error("event-driven run failed (" + std::string(to_string(r.status)) +
                             "): " + r.message);
  RunTimer converting;
  converting.start(RunTimer::Phase::kRecord);
  out.finish_recording();
  for (const auto& e : r.events)
    out.events.push_back({e.t, e.contact, std::string(to_string(e.kind)),
                          std::string(to_string(e.from_mode)), std::string(to_string(e.to_mode)),
                          e.impulse_n, e.impulse_t_scalar()});
  // The rest declared at a Zeno cut-off stands for the impacts that accumulate at t∞, which the
  // engine predicts from the geometric series of the flights: reported as an event of its own.
  const std::vector<ZenoLimit> limits = zeno_limits(r.events);
  for (const ZenoLimit& limit : limits)
    out.events.push_back({limit.t, limit.contact, "zeno_limit", std::string(to_string(limit.mode)),
                          std::string(to_string(limit.mode)), 0.0, 0.0});
  std::stable_sort(
      out.events.begin(), out.events.end(),
      [](const output::EventRecord& a, const output::EventRecord& b) { return a.t < b.t; });
  for (int k = 0; k < kNumEventKinds; ++k)
    out.summary.emplace_back(std::string(to_string(static_cast<EventKind>(k))) + " events",
                             std::to_string(r.summary.counts[static_cast<std::size_t>(k)]));
  for (const ZenoLimit& limit : limits)
    out.summary.emplace_back("zeno limit of " + limit.contact + " [s]",
                             output::number_text(limit.t));
  out.summary.emplace_back("integrator steps (method)", std::to_string(r.summary.steps));
  out.summary.emplace_back("rhs evaluations", std::to_string(r.summary.rhs_evaluations));
  out.summary.emplace_back("root function evaluations", std::to_string(r.summary.root_evaluations));
  out.summary.emplace_back("tracked contacts (most in one segment)",
                           std::to_string(r.summary.max_tracked_contacts));
  out.summary.emplace_back("contact problems solved by enumeration after the LCP solver failed",
                           std::to_string(r.summary.enumerated_contact_problems));
  out.step_count = r.summary.steps;
  out.unconverged_steps = 0;  // a contact problem that is not solved ends the run
  out.mean_contacts = mean_closed_contacts(r);
  out.max_penetration = penetration.deepest();
  converting.stop();
  out.engine_cpu_seconds = r.summary.engine_cpu_seconds;
  out.record_cpu_seconds = r.summary.record_cpu_seconds + converting.record_cpu_seconds();
  out.wall_seconds = r.summary.wall_seconds + converting.wall_seconds();
  return out;
}

}  // namespace impactbench::engines::event_driven
