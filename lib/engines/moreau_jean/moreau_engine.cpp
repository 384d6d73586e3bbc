#include "lib/engines/moreau_jean/moreau_engine.hpp"

#include <chrono>
#include <map>
#include <stdexcept>

#include "lib/engines/engine_settings.hpp"
#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/output/message_text.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

const std::string kEngine = "moreau";

ContactSample contact_sample(const ContactImpulse& impulse) {
  ContactSample s;
  s.name = impulse.name;
  s.gap = impulse.gap;
  s.impulse_n = impulse.r_n;
  s.friction = impulse.friction;
  const auto d = impulse.r_t.size();
  s.impulse_t.head(d) = impulse.r_t;
  if (impulse.u_after.size() > 0) {
    s.velocity_n = impulse.u_after[0];
    s.velocity_t.head(d) = impulse.u_after.tail(d);
  }
  return s;
}

}  // namespace

MoreauJeanOptions options_from(const RunOptions& run) {
  MoreauJeanOptions o;
  if (run.dt > 0.0) o.dt = run.dt;
  if (!run.solver.empty()) o.solver = run.solver;
  apply_settings(
      kEngine, run.settings,
      {{"theta", [&](const std::string& v) { o.theta = setting_number(kEngine, "theta", v); }},
       {"on_failure",
        [&](const std::string& v) {
          if (v != "stop" && v != "warn")
            throw std::invalid_argument("moreau: setting 'on_failure' must be stop or warn");
          o.on_failure = v == "stop" ? OnFailure::kStop : OnFailure::kWarn;
        }},
       {"forces",
        [&](const std::string& v) {
          if (v != "explicit" && v != "linearly-implicit")
            throw std::invalid_argument(
                "moreau: setting 'forces' must be explicit or linearly-implicit");
          o.forces =
              v == "explicit" ? ForceTreatment::kExplicit : ForceTreatment::kLinearlyImplicit;
        }},
       {"tolerance",
        [&](const std::string& v) { o.tolerance = setting_number(kEngine, "tolerance", v); }},
       {"max_iterations",
        [&](const std::string& v) {
          o.max_iterations = setting_int(kEngine, "max_iterations", v);
        }},
       {"contact_margin",
        [&](const std::string& v) {
          o.contact_margin = setting_number(kEngine, "contact_margin", v);
        }},
       {"cone_facets",
        [&](const std::string& v) { o.cone_facets = setting_int(kEngine, "cone_facets", v); }}});
  validate(o);
  return o;
}

RunResult run_moreau_jean(const scenario::Scenario& scenario, const RunOptions& run) {
  const MoreauJeanOptions options = options_from(run);
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
  out.trajectory.position_names = built.system->position_names();
  out.trajectory.velocity_names = built.system->velocity_names();
  std::map<std::string, bool> active_before;
  const auto observer = [&](const MoreauJeanState& state, const StepReport& report) {
    out.add_sample(state.t, state.q, state.v, built.system->energy(state.q, state.v));
    if (report.statistics.step_index == 0) return;
    StepRecord step;
    step.t = report.statistics.t;
    step.active_contacts = report.statistics.active_contacts;
    step.iterations = report.statistics.solver_iterations;
    step.residual = report.statistics.residual;
    step.solve_seconds = report.statistics.solve_seconds;
    step.converged = report.statistics.converged;
    std::map<std::string, bool> active_now;
    for (const ContactImpulse& impulse : report.impulses) {
      step.contacts.push_back(contact_sample(impulse));
      if (impulse.r_n <= 0.0) continue;
      active_now[impulse.name] = true;
      if (!active_before.count(impulse.name))
        out.events.push_back({step.t, impulse.name, "impact", "open", "closed", impulse.r_n,
                              impulse.r_t.size() > 0 ? impulse.r_t.norm() : 0.0});
    }
    for (const auto& [name, unused] : active_before)
      if (!active_now.count(name))
        out.events.push_back({step.t, name, "liftoff", "closed", "open", 0.0, 0.0});
    active_before = std::move(active_now);
    out.steps.push_back(std::move(step));
  };

  const auto start = std::chrono::steady_clock::now();
  const double duration = run.duration > 0.0 ? run.duration : scenario.duration;
  const SimulationResult r = stepper.simulate(built.q0, built.v0, input, duration, observer);
  out.cpu_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.succeeded())
    throw std::runtime_error("moreau: run stopped at t = " + output::number_text(r.final_state.t) +
                             " (" + to_string(r.status) + "): " + r.message);
  out.settings = {{"dt", std::to_string(options.dt)},
                  {"theta", std::to_string(options.theta)},
                  {"solver", options.solver},
                  {"tolerance", std::to_string(options.tolerance)},
                  {"max_iterations", std::to_string(options.max_iterations)}};
  out.summary = {{"steps", std::to_string(r.summary.steps)},
                 {"max_active_contacts", std::to_string(r.summary.max_active_contacts)},
                 {"solver_failures", std::to_string(r.summary.solver_failures)},
                 {"worst_residual", std::to_string(r.summary.worst_residual)},
                 {"solver_iterations", std::to_string(r.summary.total_solver_iterations)}};
  return out;
}

}  // namespace impactbench::engines::moreau_jean
