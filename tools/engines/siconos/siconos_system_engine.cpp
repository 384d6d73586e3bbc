#include "tools/engines/siconos/siconos_system_engine.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "lib/engines/step_count.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/metrics/penetration.hpp"
#include "lib/output/number_text.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/fixed_step/fixed_step_driver.hpp"
#include "tools/engines/fixed_step/reference_scene.hpp"
#include "tools/engines/siconos/siconos_lagrangian_model.hpp"
#include "tools/engines/siconos/siconos_scheme_settings.hpp"

namespace impactbench::adapters {
namespace {

constexpr auto kBuiltIn = engines::SettingSource::kBuiltIn;
/// A find_contacts margin past every gap: the contact set of a body against planes, or of the
/// plank-box, is then all of its potential contacts, always in the same order.
constexpr double kEveryContact = 1e30;  // [m]

// F = S(q) u(t) − H(q, v) at the model's q = to_model(s) and its Jacobians with respect to
// Siconos' coordinates s by central differences. The Jacobians only steer Siconos' Newton
// iteration (and its W = M − hθ ∂F/∂v − h²θ² ∂F/∂s): the step it converges to solves the
// θ-method's equations whatever they are, to the Newton tolerance.
template <typename ToModel>
siconos::LagrangianForces model_forces(const model::LagrangianSystem<double>& system,
                                       const scenario::Scenario& scenario, double t,
                                       const Eigen::VectorXd& s, const Eigen::VectorXd& v,
                                       const ToModel& to_model) {
  const int nu = system.num_inputs();
  const Eigen::VectorXd u = nu == 0 || scenario.inputs.empty()
                                ? Eigen::VectorXd(Eigen::VectorXd::Zero(nu))
                                : scenario.input(t);
  auto force = [&](const Eigen::VectorXd& ss, const Eigen::VectorXd& vv) -> Eigen::VectorXd {
    const Eigen::VectorXd q = to_model(ss);
    Eigen::VectorXd f = -system.bias_forces(q, vv);
    if (nu > 0) f += system.input_matrix(q) * u;
    return f;
  };
  siconos::LagrangianForces out;
  out.f = force(s, v);
  const Eigen::Index n = s.size();
  out.dq.resize(n, n);
  out.dv.resize(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double ds = 1e-6 * std::max(1.0, std::abs(s[i]));
    const double dv = 1e-6 * std::max(1.0, std::abs(v[i]));
    Eigen::VectorXd sp = s, sm = s, vp = v, vm = v;
    sp[i] += ds;
    sm[i] -= ds;
    vp[i] += dv;
    vm[i] -= dv;
    out.dq.col(i) = (force(sp, v) - force(sm, v)) / (2 * ds);
    out.dv.col(i) = (force(s, vp) - force(s, vm)) / (2 * dv);
  }
  return out;
}

siconos::ContactKinematics contact_kinematics(const model::Contact<double>& c, int nv) {
  siconos::ContactKinematics k;
  k.gap = c.gap;
  const int d = c.tangent_dim();
  k.jacobian.resize(1 + d, nv);
  k.jacobian.row(0) = c.normal_direction(nv).transpose();
  k.jacobian.bottomRows(d) = c.tangent_directions(nv).transpose();
  return k;
}

bool is_single_sphere(const scenario::Scenario& scenario) {
  return scenario.dimension == scenario::Dimension::kSpatial && scenario.bodies.size() == 1 &&
         scenario.bodies.front().shape == model::ShapeKind::kSphere;
}

// Throws UnsupportedScene for a system Siconos' Lagrangian model does not state.
void check_stated(const model::LagrangianSystem<double>& system,
                  const engines::SiconosSettings& settings, bool sphere) {
  if (system.num_positions() != system.num_velocities() && !sphere)
    throw UnsupportedScene("siconos: the system's positions and velocities differ in number");
  if (sphere && settings.solver != engines::SiconosSolver::kNsgs)
    throw UnsupportedScene(
        "siconos: spatial contacts are solved by fc3d nsgs only (solver = "
        "nsgs), not by the planar fc2d solver given");
}

// What the run compiles in; the registry adds the settings in force.
engines::SettingList built_in_settings(const siconos::NewtonLoop& newton, bool sphere) {
  return {
      {"precision", "double", kBuiltIn},
      {"integrator", "MoreauJeanOSI + TimeStepping, Newton loop on the forces", kBuiltIn},
      {"newton tolerance", output::number_text(newton.tolerance), kBuiltIn},
      {"newton max iterations", std::to_string(newton.max_iterations), kBuiltIn},
      {"contact problem",
       sphere ? "FrictionContact (dimension 3, fc3d nsgs)"
              : "FrictionContact (dimension 2, fc2d solvers)",
       kBuiltIn},
      {"dynamical system", "LagrangianDS with the project's mass, forces (F = S u - H)", kBuiltIn},
      {"contact relation", "LagrangianScleronomousR per model contact (its gap and Jacobian)",
       kBuiltIn}};
}

// Siconos' MoreauJeanOSI on the model, stepped by the fixed-step loop. Siconos integrates
// its own coordinates s; q and v are the model's, carried by the adapter (see to_model).
struct SiconosSystemWorld : FixedStepWorld {
  SiconosSystemWorld(const model::LagrangianSystem<double>& system_,
                     const engines::SiconosSettings& settings_, siconos::LagrangianModel& model_,
                     std::function<Eigen::VectorXd(const Eigen::VectorXd&)> to_model_, bool sphere_,
                     Eigen::VectorXd& q_, Eigen::VectorXd& v_,
                     std::vector<model::Contact<double>>& found_)
      : system(system_),
        settings(settings_),
        model(model_),
        to_model(std::move(to_model_)),
        sphere(sphere_),
        q(q_),
        v(v_),
        found(found_),
        penetration(system_) {}

  void record_state(double t, engines::RunResult& result) override {
    penetration.add(q, v);
    result.add_sample(t, q, v, system.energy(q, v));
  }

  // Siconos' activation rule (MoreauJeanOSI's addInteractionInIndexSet) on the state at the
  // step's start: these are the contacts of the step's problem.
  void before_step(double) override {
    system.find_contacts(q, v, kEveryContact, found);
    active.clear();
    approach.assign(found.size(), 0.0);
    for (std::size_t i = 0; i < found.size(); ++i) {
      const double rate = found[i].relative_velocity(v)[0];
      approach[i] = -rate;
      if (found[i].gap + settings.gamma * settings.dt * rate <= settings.activation_threshold)
        active.push_back(static_cast<int>(i));
    }
  }

  void step(double) override { model.step(); }

  std::vector<engines::ClosedContact> read_step(double, engines::StepRecord& step,
                                                engines::RunResult&) override {
    const double h = settings.dt;
    newton_total += model.newton_iterations();
    newton_unconverged += model.newton_converged() ? 0 : 1;
    step.active_contacts = static_cast<int>(active.size());
    if (!active.empty()) {
      step.iterations = model.iterations();
      step.residual = model.residual();
      step.converged = step.residual <= settings.tolerance;
    }
    const Eigen::VectorXd v_start = v;
    v = model.v();
    if (sphere) {  // the orientation from the θ-method's velocity, the position from Siconos
      q = system.integrate_position(q, (1 - settings.theta) * v_start + settings.theta * v, h);
      q.head(3) = model.q().head(3);
    } else {
      q = model.q();
    }
    // The step's contact law holds in the frame of the contact Jacobians its last contact
    // problem used (Siconos' last Newton iterate before the new state).
    if (keep_steps)
      system.find_contacts(to_model(model.law_frame_point()), v, kEveryContact, law_frame);
    return closed_contacts(step);
  }

  std::vector<engines::ClosedContact> closed_contacts(engines::StepRecord& step) const {
    std::vector<engines::ClosedContact> closed;
    for (const int index : active) {
      const Eigen::VectorXd impulse = model.impulse(index);
      const Eigen::Index d = impulse.size() - 1;
      const auto& c = found[static_cast<std::size_t>(index)];
      if (keep_steps) {
        engines::ContactSample sample;
        sample.name = c.name;
        sample.gap = c.gap;
        sample.impulse_n = impulse[0];
        sample.impulse_t.head(d) = impulse.tail(d);
        const Eigen::VectorXd u_after =
            law_frame[static_cast<std::size_t>(index)].relative_velocity(v);
        sample.velocity_n = u_after[0];
        sample.velocity_t.head(d) = u_after.tail(d);
        sample.velocity_n_before = -approach[static_cast<std::size_t>(index)];
        sample.friction = c.friction;
        sample.restitution = c.restitution;
        step.contacts.push_back(sample);
      }
      if (impulse[0] > 0.0)
        closed.push_back({c.name, approach[static_cast<std::size_t>(index)], impulse[0],
                          d == 1 ? impulse[1] : impulse.tail(d).norm()});
    }
    return closed;
  }

  const model::LagrangianSystem<double>& system;
  const engines::SiconosSettings& settings;
  siconos::LagrangianModel& model;
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> to_model;
  bool sphere = false;
  Eigen::VectorXd& q;
  Eigen::VectorXd& v;
  std::vector<model::Contact<double>>& found;
  metrics::PenetrationTracker penetration;
  bool keep_steps = true;
  std::vector<int> active;
  std::vector<double> approach;
  std::vector<model::Contact<double>> law_frame;
  long newton_total = 0, newton_unconverged = 0;
};

}  // namespace

bool siconos_states_as_system(const scenario::Scenario& scenario,
                              const engines::SiconosSettings& settings) {
  if (scenario.system == scenario::SystemKind::kPlankBox) return true;
  const bool one_planar_body =
      scenario.dimension == scenario::Dimension::kPlanar && scenario.bodies.size() == 1;
  return settings.scheme == engines::SiconosScheme::kMoreauJean &&
         (one_planar_body || is_single_sphere(scenario));
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
  const long steps = engines::fixed_step_count(engine_name::kSiconos, duration, h);
  const engines::BuiltSystem built = engines::build_system(scenario);
  const model::LagrangianSystem<double>& system = *built.system;
  const int nv = system.num_velocities();
  const bool sphere = is_single_sphere(scenario);
  check_stated(system, settings, sphere);

  // The coordinates s Siconos integrates: the model's q where they are as many as its
  // velocities (planar bodies, the plank-box). For a sphere (q: position and unit quaternion)
  // the position and three angles Siconos integrates as their rates ω and nothing reads: a
  // sphere's mass (isotropic), forces and contacts do not depend on its orientation, which we
  // carry along from the steps' velocities with the model's integrate_position.
  Eigen::VectorXd q = built.q0, v = built.v0;
  auto to_siconos = [&](const Eigen::VectorXd& model_q) -> Eigen::VectorXd {
    if (!sphere) return model_q;
    Eigen::VectorXd s_q = Eigen::VectorXd::Zero(nv);
    s_q.head(3) = model_q.head(3);
    return s_q;
  };
  auto to_model = [&](const Eigen::VectorXd& s_q) -> Eigen::VectorXd {
    if (!sphere) return s_q;
    Eigen::VectorXd model_q = q;
    model_q.head(3) = s_q.head(3);
    return model_q;
  };

  // The model's potential contacts, found with a margin past every gap, are a fixed set (a
  // body's points against each plane, the plank–box's two corners): one Siconos interaction
  // each, in the order find_contacts gives them.
  std::vector<model::Contact<double>> found;
  system.find_contacts(built.q0, built.v0, kEveryContact, found);
  const std::vector<model::Contact<double>> initial = found;
  siconos::LagrangianProblem problem;
  problem.q0 = to_siconos(built.q0);
  problem.v0 = built.v0;
  problem.mass = Eigen::MatrixXd(system.mass_matrix(built.q0));
  problem.forces = [&](double t, const Eigen::VectorXd& s_q, const Eigen::VectorXd& s_v) {
    return model_forces(system, scenario, t, s_q, s_v, to_model);
  };
  problem.contacts = static_cast<int>(initial.size());
  std::vector<model::Contact<double>> scratch;
  problem.kinematics = [&](int index, const Eigen::VectorXd& s_q) {
    system.find_contacts(to_model(s_q), Eigen::VectorXd::Zero(nv), kEveryContact, scratch);
    if (scratch.size() != initial.size())
      throw std::runtime_error("siconos: the model's contact set changed size");
    return contact_kinematics(scratch[static_cast<std::size_t>(index)], nv);
  };
  for (const auto& c : initial) {
    problem.restitution.push_back(c.restitution);
    problem.friction.push_back(c.friction);
  }
  siconos::Scheme scheme = moreau_jean_scheme(settings, h, steps);
  scheme.contact_dimension = 1 + system.tangent_dim();
  const siconos::NewtonLoop newton;
  siconos::LagrangianModel model(problem, scheme, newton);

  engines::RunResult result;
  result.recording = recording;
  result.engine = engine_name::kSiconos;
  result.trajectory.position_names = system.position_names();
  result.trajectory.velocity_names = system.velocity_names();
  result.settings = built_in_settings(newton, sphere);

  SiconosSystemWorld world{system, settings, model, to_model, sphere, q, v, found};
  world.keep_steps = recording.keep_steps;
  run_fixed_steps(world, {engine_name::kSiconos, h, duration, settings.impact, true}, result);
  result.max_penetration = world.penetration.deepest();
  result.summary = {{"newton_iterations", std::to_string(world.newton_total)},
                    {"newton_unconverged_steps", std::to_string(world.newton_unconverged)}};
  return result;
}

}  // namespace impactbench::adapters
