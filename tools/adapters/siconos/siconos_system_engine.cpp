#include "tools/adapters/siconos/siconos_system_engine.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "lib/engines/contact_events.hpp"
#include "lib/engines/run_timer.hpp"
#include "lib/engines/step_count.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/metrics/penetration.hpp"
#include "lib/output/number_text.hpp"
#include "tools/adapters/reference_scene.hpp"
#include "tools/adapters/siconos/siconos_lagrangian_model.hpp"
#include "tools/adapters/siconos/siconos_scheme_settings.hpp"

namespace impactbench::adapters {
namespace {

constexpr auto kBuiltIn = engines::SettingSource::kBuiltIn;
/// A find_contacts margin past every gap: the contact set of a body against planes, or of the
/// plank-box, is then all of its potential contacts, always in the same order.
constexpr double kEveryContact = 1e30;  // [m]

// F = S(q) u(t) − H(q, v) and its Jacobians by central differences. The Jacobians only steer
// Siconos' Newton iteration (and its W = M − hθ ∂F/∂v − h²θ² ∂F/∂q): the step it converges to
// solves the θ-method's equations whatever they are, to the Newton tolerance.
siconos::LagrangianForces model_forces(const model::LagrangianSystem<double>& system,
                                       const scenario::Scenario& scenario, double t,
                                       const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  const int nu = system.num_inputs();
  const Eigen::VectorXd u = nu == 0 || scenario.inputs.empty()
                                ? Eigen::VectorXd(Eigen::VectorXd::Zero(nu))
                                : scenario.input(t);
  auto force = [&](const Eigen::VectorXd& qq, const Eigen::VectorXd& vv) -> Eigen::VectorXd {
    Eigen::VectorXd f = -system.bias_forces(qq, vv);
    if (nu > 0) f += system.input_matrix(qq) * u;
    return f;
  };
  siconos::LagrangianForces out;
  out.f = force(q, v);
  const Eigen::Index n = q.size();
  out.dq.resize(n, n);
  out.dv.resize(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double dq = 1e-6 * std::max(1.0, std::abs(q[i]));
    const double dv = 1e-6 * std::max(1.0, std::abs(v[i]));
    Eigen::VectorXd qp = q, qm = q, vp = v, vm = v;
    qp[i] += dq;
    qm[i] -= dq;
    vp[i] += dv;
    vm[i] -= dv;
    out.dq.col(i) = (force(qp, v) - force(qm, v)) / (2 * dq);
    out.dv.col(i) = (force(q, vp) - force(q, vm)) / (2 * dv);
  }
  return out;
}

siconos::ContactKinematics contact_kinematics(const model::Contact<double>& c, int nv) {
  siconos::ContactKinematics k;
  k.gap = c.gap;
  k.jacobian.resize(2, nv);
  k.jacobian.row(0) = c.normal_direction(nv).transpose();
  k.jacobian.row(1) = c.tangent_directions(nv).col(0).transpose();
  return k;
}

}  // namespace

bool siconos_states_as_system(const scenario::Scenario& scenario,
                              const engines::SiconosSettings& settings) {
  if (scenario.system == scenario::SystemKind::kPlankBox) return true;
  return settings.scheme == engines::SiconosScheme::kMoreauJean &&
         scenario.dimension == scenario::Dimension::kPlanar && scenario.bodies.size() == 1;
}

engines::RunResult run_siconos_system(const scenario::Scenario& scenario,
                                      const engines::SiconosSettings& settings, double duration,
                                      const engines::RecordingOptions& recording) {
  if (settings.scheme == engines::SiconosScheme::kEventDriven)
    throw UnsupportedScene(
        "siconos: scheme event_driven states disks and boxes against planes "
        "only, not the '" +
        scenario.name + "' system (use scheme moreau_jean)");
  const double h = settings.dt;
  const long steps = engines::fixed_step_count("siconos", duration, h);
  const engines::BuiltSystem built = engines::build_system(scenario);
  const model::LagrangianSystem<double>& system = *built.system;
  if (system.tangent_dim() != 1)
    throw UnsupportedScene("siconos: only planar systems are stated as Lagrangian systems");
  const int nv = system.num_velocities();
  if (system.num_positions() != nv)
    throw UnsupportedScene("siconos: the system's positions and velocities differ in number");

  // The model's contacts are fixed (both corners of the plank–box, whatever their gap): one
  // Siconos interaction each, in the order find_contacts gives them.
  std::vector<model::Contact<double>> found;
  system.find_contacts(built.q0, built.v0, kEveryContact, found);
  const std::vector<model::Contact<double>> initial = found;
  siconos::LagrangianProblem problem;
  problem.q0 = built.q0;
  problem.v0 = built.v0;
  problem.mass = Eigen::MatrixXd(system.mass_matrix(built.q0));
  problem.forces = [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    return model_forces(system, scenario, t, q, v);
  };
  problem.contacts = static_cast<int>(initial.size());
  std::vector<model::Contact<double>> scratch;
  problem.kinematics = [&](int index, const Eigen::VectorXd& q) {
    system.find_contacts(q, Eigen::VectorXd::Zero(nv), kEveryContact, scratch);
    if (scratch.size() != initial.size())
      throw std::runtime_error("siconos: the model's contact set changed size");
    return contact_kinematics(scratch[static_cast<std::size_t>(index)], nv);
  };
  for (const auto& c : initial) {
    problem.restitution.push_back(c.restitution);
    problem.friction.push_back(c.friction);
  }
  const siconos::Scheme scheme = moreau_jean_scheme(settings, h, steps);
  const siconos::NewtonLoop newton;
  siconos::LagrangianModel model(problem, scheme, newton);

  engines::RunResult result;
  result.recording = recording;
  result.engine = "siconos";
  result.trajectory.position_names = system.position_names();
  result.trajectory.velocity_names = system.velocity_names();
  result.settings = {
      {"precision", "double", kBuiltIn},
      {"integrator", "MoreauJeanOSI + TimeStepping, Newton loop on the forces", kBuiltIn},
      {"newton tolerance", output::number_text(newton.tolerance), kBuiltIn},
      {"newton max iterations", std::to_string(newton.max_iterations), kBuiltIn},
      {"contact problem", "FrictionContact (dimension 2, fc2d solvers)", kBuiltIn},
      {"dynamical system", "LagrangianDS with the project's mass, forces (F = S u - H)", kBuiltIn},
      {"contact relation", "LagrangianScleronomousR per model contact (its gap and Jacobian)",
       kBuiltIn}};

  metrics::PenetrationTracker penetration(system);
  engines::ContactEvents events(settings.impact);
  engines::RunTimer timer;
  timer.start(engines::RunTimer::Phase::kRecord);
  Eigen::VectorXd q = built.q0, v = built.v0;
  penetration.add(q, v);
  result.add_sample(0.0, q, v, system.energy(q, v));
  long newton_total = 0, newton_unconverged = 0;
  std::vector<model::Contact<double>> law_frame;
  for (long k = 0; k < steps; ++k) {
    // Siconos' activation rule on the state at the step's start (as siconos_engine.cpp).
    system.find_contacts(q, v, kEveryContact, found);
    std::vector<int> active;
    std::vector<double> approach(found.size());
    for (std::size_t i = 0; i < found.size(); ++i) {
      const double rate = found[i].relative_velocity(v)[0];
      approach[i] = -rate;
      if (found[i].gap + settings.gamma * h * rate <= settings.activation_threshold)
        active.push_back(static_cast<int>(i));
    }
    timer.switch_to(engines::RunTimer::Phase::kEngine);
    model.step();
    timer.switch_to(engines::RunTimer::Phase::kRecord);
    newton_total += model.newton_iterations();
    newton_unconverged += model.newton_converged() ? 0 : 1;
    const double t_end = static_cast<double>(k + 1) * h;
    engines::StepRecord step;
    step.t = t_end;
    step.active_contacts = static_cast<int>(active.size());
    if (!active.empty()) {
      step.iterations = model.iterations();
      step.residual = model.residual();
      step.converged = step.residual <= settings.tolerance;
    }
    std::vector<engines::ClosedContact> closed;
    q = model.q();
    v = model.v();
    // The step's contact law holds in the frame Siconos took its contact Jacobians in: at its
    // last Newton iterate of q_k+1 (q_k + h v_k, its predictor, when one iteration converged).
    if (recording.keep_steps)
      system.find_contacts(model.jacobian_point(), v, kEveryContact, law_frame);
    for (const int index : active) {
      const Eigen::Vector2d impulse = model.impulse(index);
      const auto& c = found[static_cast<std::size_t>(index)];
      if (recording.keep_steps) {
        engines::ContactSample sample;
        sample.name = c.name;
        sample.gap = c.gap;
        sample.impulse_n = impulse[0];
        sample.impulse_t.x() = impulse[1];
        const Eigen::VectorXd u_after =
            law_frame[static_cast<std::size_t>(index)].relative_velocity(v);
        sample.velocity_n = u_after[0];
        sample.velocity_t.x() = u_after[1];
        sample.friction = c.friction;
        step.contacts.push_back(sample);
      }
      if (impulse[0] > 0.0)
        closed.push_back(
            {c.name, approach[static_cast<std::size_t>(index)], impulse[0], impulse[1]});
    }
    events.after_step(t_end, closed, result.events);
    result.add_step(std::move(step));
    penetration.add(q, v);
    result.add_sample(t_end, q, v, system.energy(q, v));
  }
  result.finish_recording();
  result.max_penetration = penetration.deepest();
  result.count_steps(/*has_tolerance=*/true);
  timer.stop();
  result.set_timing(timer);
  result.summary = {{"newton_iterations", std::to_string(newton_total)},
                    {"newton_unconverged_steps", std::to_string(newton_unconverged)}};
  return result;
}

}  // namespace impactbench::adapters
