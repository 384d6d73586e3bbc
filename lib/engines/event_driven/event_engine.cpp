#include "lib/engines/event_driven/event_engine.hpp"

#include <functional>
#include <map>
#include <stdexcept>
#include <string>

#include "lib/engines/engine_settings.hpp"
#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/engines/step_count.hpp"
#include "lib/engines/system_builder.hpp"
#include "solvers/lcp/lcp_solvers.hpp"

namespace impactbench::engines::event_driven {
namespace {

const std::string kEngine = "event";
double number(const std::string& key, const std::string& value) {
  return setting_number(kEngine, key, value);
}
int whole(const std::string& key, const std::string& value) {
  return setting_int(kEngine, key, value);
}

bool is_lcp_solver(const std::string& name) {
  for (const auto& info : solvers::lcp_solvers())
    if (info.name == name) return true;
  return false;
}

}  // namespace

EventDrivenOptions options_from(const RunOptions& run) {
  EventDrivenOptions o;
  if (run.tolerance > 0.0) o.relative_tolerance = o.absolute_tolerance = run.tolerance;
  if (!run.solver.empty())
    (is_lcp_solver(run.solver) ? o.lcp_solver : o.friction_solver) = run.solver;
  apply_settings(
      kEngine, run.settings,
      {{"rtol", [&](const std::string& v) { o.relative_tolerance = number("rtol", v); }},
       {"atol", [&](const std::string& v) { o.absolute_tolerance = number("atol", v); }},
       {"method",
        [&](const std::string& v) {
          if (v != "bdf" && v != "adams")
            throw std::invalid_argument("event: setting 'method' must be bdf or adams");
          o.method = v == "bdf" ? MultistepMethod::kBdf : MultistepMethod::kAdams;
        }},
       {"max_events", [&](const std::string& v) { o.max_events = whole("max_events", v); }},
       {"output_interval",
        [&](const std::string& v) { o.output_interval = number("output_interval", v); }},
       {"max_step", [&](const std::string& v) { o.max_step = number("max_step", v); }},
       {"zeno_impact_count",
        [&](const std::string& v) { o.zeno_impact_count = whole("zeno_impact_count", v); }},
       {"zeno_velocity",
        [&](const std::string& v) { o.zeno_velocity = number("zeno_velocity", v); }},
       {"zeno_min_interval",
        [&](const std::string& v) { o.zeno_min_interval = number("zeno_min_interval", v); }},
       {"gap_tolerance",
        [&](const std::string& v) { o.gap_tolerance = number("gap_tolerance", v); }},
       {"velocity_tolerance",
        [&](const std::string& v) { o.velocity_tolerance = number("velocity_tolerance", v); }},
       {"lcp_solver", [&](const std::string& v) { o.lcp_solver = v; }},
       {"friction_solver", [&](const std::string& v) { o.friction_solver = v; }}});
  return o;
}

RunResult run_event_driven(const scenario::Scenario& scenario, const RunOptions& run) {
  const EventDrivenOptions options = options_from(run);
  const BuiltSystem built = build_system(scenario);
  const EventDrivenIntegrator integrator(*built.system, options);
  // A scenario without force inputs (e.g. the plank–box at rest) leaves u = 0.
  EventDrivenIntegrator::Input input;
  if (!scenario.inputs.empty()) input = [&scenario](double t) { return scenario.input(t); };
  const double duration = run.duration > 0.0 ? run.duration : scenario.duration;
  // Samples are kept in memory like the steps of the time-stepping engines.
  if (options.output_interval > 0.0)
    checked_step_count(kEngine, duration, options.output_interval, "output_interval");
  const EventDrivenResult r = integrator.simulate(built.q0, built.v0, input, duration);
  if (!r.succeeded())
    throw std::runtime_error("event-driven run failed (" + std::string(to_string(r.status)) +
                             "): " + r.message);
  RunResult out;
  out.engine = "event";
  out.trajectory.position_names = built.system->position_names();
  out.trajectory.velocity_names = built.system->velocity_names();
  for (const auto& s : r.samples) out.add_sample(s.t, s.q, s.v, s.energy);
  for (const auto& e : r.events)
    out.events.push_back({e.t, e.contact, std::string(to_string(e.kind)),
                          std::string(to_string(e.from_mode)), std::string(to_string(e.to_mode)),
                          e.impulse_n, e.impulse_t_scalar()});
  out.settings = {{"rtol", std::to_string(options.relative_tolerance)},
                  {"atol", std::to_string(options.absolute_tolerance)},
                  {"method", options.method == MultistepMethod::kBdf ? "bdf" : "adams"},
                  {"lcp_solver", options.lcp_solver},
                  {"friction_solver", options.friction_solver}};
  for (int k = 0; k < kNumEventKinds; ++k)
    out.summary.emplace_back(std::string(to_string(static_cast<EventKind>(k))) + " events",
                             std::to_string(r.summary.counts[static_cast<std::size_t>(k)]));
  out.summary.emplace_back("cvode steps", std::to_string(r.summary.steps));
  out.summary.emplace_back("rhs evaluations", std::to_string(r.summary.rhs_evaluations));
  out.cpu_seconds = r.summary.cpu_seconds;
  return out;
}

}  // namespace impactbench::engines::event_driven
