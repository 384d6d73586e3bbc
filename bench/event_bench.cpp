// Event-driven integrator benchmarks on the analytic scenarios (systems from the model library):
//   BM_EventScenario/<scenario>: CPU time per event and per simulated second, with the CVODE
//     work (steps, right-hand sides, guard evaluations) per run, at the default tolerance 1e-10;
//   BM_EventScenarioFastRestart/<scenario>: the same with startup_order = 2 and
//     dense_output_root_search (faster, not bit-identical: see event_driven_options.hpp);
//   BM_EventScenarioErk/<scenario>: the same with method = erk (ARKODE's explicit Runge–Kutta
//     pair instead of CVODE), and BM_EventScenarioErkDenseRoots with dense_output_root_search;
//   BM_EventScenarioOwnErk/<scenario>: method = own_erk (the same Dormand–Prince pair stepped by
//     our own driver, roots on the dense output);
//   BM_EventScenarioNoSamples/<scenario>: CVODE at its defaults with output_interval = 0 (no
//     samples between events: the stepping without the recording of 100 Hz samples);
//   BM_EventScenarioPaired/<scenario>: CVODE at its defaults, with the fast restart, ERK and
//     own_erk, alternating run by run in one benchmark, with each one's CPU time per event as
//     counters;
//   BM_EventWorkPrecision/<scenario>/<k>: tolerance 10^-k, k = 4..12, with the error against
//     the analytical solution as a counter, for work-precision plots (error vs CPU time);
//     BM_EventWorkPrecisionStartup and …DenseRoots the same with either half of the fast
//     restart (startup_order = 2, dense_output_root_search), whose errors decide whether it
//     could be the default, and BM_EventWorkPrecisionOwnErk with method = own_erk.
// Scenario errors: bouncing_ball the largest relative error of the first 10 impact times;
// sliding_block / incline_push the relative error of the stop / slip time; rocking_block the
// largest relative error of the pre-impact angular speeds against energy conservation and
// Housner's ratio 1 − 1.5 sin²α per impact; plank_box (a tilted landing) the relative error of
// the second corner's impact time against a run at tolerance 1e-13; sphere_spin the relative error
// of the slip→roll time 2‖c₀‖/(7μg).
#include <algorithm>
#include <cmath>
#include <ctime>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>
#include <Eigen/Geometry>

#include "common/registered_main.hpp"
#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/model/planar/planar_system.hpp"
#include "lib/model/plank_box/plank_box_system.hpp"
#include "lib/model/spatial/spatial_system.hpp"

namespace {

using impactbench::engines::event_driven::EventDrivenIntegrator;
using impactbench::engines::event_driven::EventDrivenOptions;
using impactbench::engines::event_driven::EventDrivenResult;
using impactbench::engines::event_driven::EventKind;
using impactbench::engines::event_driven::FlowMethod;
namespace model = impactbench::model;
constexpr double g = 9.81;

struct Scenario {
  std::shared_ptr<model::LagrangianSystem<double>> system;
  Eigen::VectorXd q0, v0;
  EventDrivenIntegrator::Input input;
  double duration = 1.0;
  /// Error of a run against the analytical solution (NaN when the run failed).
  std::function<double(const EventDrivenResult&)> error;
};

std::shared_ptr<model::LagrangianSystem<double>> planar_body(model::ShapeKind shape, double w,
                                                             double h, double mu, double e,
                                                             const Eigen::Vector2d& normal,
                                                             bool pushed = false) {
  model::BodySpec body;
  body.name = "body";
  body.shape = shape;
  body.radius = w;
  body.size = Eigen::Vector3d(w, h, 0.0);
  body.mass = 1.0;
  model::StaticPlaneSpec plane;
  plane.normal = Eigen::Vector3d(normal.x(), normal.y(), 0.0);
  std::vector<model::ForceInputSpec> inputs;
  if (pushed) inputs.push_back({"body", Eigen::Vector3d(-normal.y(), normal.x(), 0.0)});
  return std::make_shared<model::planar::PlanarRigidBodySystemd>(
      std::vector<model::BodySpec>{body}, std::vector<model::StaticPlaneSpec>{plane}, g,
      model::Material{mu, e}, inputs);
}

std::vector<double> event_times(const EventDrivenResult& r, EventKind kind) {
  std::vector<double> t;
  for (const auto& e : r.events)
    if (e.kind == kind) t.push_back(e.t);
  return t;
}

Scenario bouncing_ball() {
  Scenario s;
  s.system = planar_body(model::ShapeKind::kDisk, 0.1, 0.1, 0.0, 0.9, Eigen::Vector2d::UnitY());
  s.q0 = Eigen::Vector3d(0, 1, 0);
  s.v0 = Eigen::Vector3d::Zero();
  s.duration = 10.0;
  s.error = [](const EventDrivenResult& r) {
    const auto t = event_times(r, EventKind::kImpact);
    if (!r.succeeded() || t.size() < 10) return std::nan("");
    double exact = std::sqrt(2 * 0.9 / g), speed = std::sqrt(2 * g * 0.9), worst = 0.0;
    for (int k = 0; k < 10; ++k) {
      worst = std::max(worst, std::abs(t[static_cast<std::size_t>(k)] - exact) / exact);
      exact += 2 * 0.9 * speed / g;
      speed *= 0.9;
    }
    return worst;
  };
  return s;
}

Scenario sliding_block() {
  Scenario s;
  s.system = planar_body(model::ShapeKind::kBox, 0.2, 0.2, 0.5, 0.0, Eigen::Vector2d::UnitY());
  s.q0 = Eigen::Vector3d(0, 0.1, 0);
  s.v0 = Eigen::Vector3d(2, 0, 0);
  s.duration = 1.0;
  s.error = [](const EventDrivenResult& r) {
    const auto t = event_times(r, EventKind::kSlipToStick);
    const double exact = 2.0 / (0.5 * g);
    return r.succeeded() && !t.empty() ? std::abs(t[0] - exact) / exact : std::nan("");
  };
  return s;
}

Scenario incline_push() {
  const double beta = 0.2, mu = 0.5, k = 2.0;
  const Eigen::Vector2d n(-std::sin(beta), std::cos(beta));
  Scenario s;
  // The input pushes along (−n_y, n_x) = down the slope.
  s.system = planar_body(model::ShapeKind::kBox, 0.2, 0.2, mu, 0.0, n, true);
  const Eigen::Vector2d centre = 0.1 * n;
  s.q0 = Eigen::Vector3d(centre.x(), centre.y(), beta);
  s.v0 = Eigen::Vector3d::Zero();
  s.input = [k](double t) { return Eigen::VectorXd::Constant(1, k * t); };
  s.duration = 2.0;
  s.error = [=](const EventDrivenResult& r) {
    const auto t = event_times(r, EventKind::kStickToSlip);
    const double exact = g * (mu * std::cos(beta) - std::sin(beta)) / k;
    return r.succeeded() && !t.empty() ? std::abs(t[0] - exact) / exact : std::nan("");
  };
  return s;
}

Scenario rocking_block() {
  const double w = 0.2, h = 0.6, theta0 = 0.1;
  Scenario s;
  s.system = planar_body(model::ShapeKind::kBox, w, h, 1.0, 0.0, Eigen::Vector2d::UnitY());
  const Eigen::Vector2d centre = -(Eigen::Rotation2Dd(theta0) * Eigen::Vector2d(-w / 2, -h / 2));
  s.q0 = Eigen::Vector3d(centre.x(), centre.y(), theta0);
  s.v0 = Eigen::Vector3d::Zero();
  s.duration = 1.5;
  // Energy gives the first pre-impact speed, ½ I_O ω₁² = m g (y_c(θ₀) − h/2) with
  // I_O = m (w² + h²)/3 about a corner, and each impact multiplies it by Housner's ratio.
  s.error = [=](const EventDrivenResult& r) {
    if (!r.succeeded()) return std::nan("");
    const double ratio = 1.0 - 1.5 * std::pow(std::sin(std::atan(w / h)), 2);
    const double drop = w / 2 * std::sin(theta0) + h / 2 * std::cos(theta0) - h / 2;
    double omega = std::sqrt(2 * g * drop * 3 / (w * w + h * h));
    const auto impacts = event_times(r, EventKind::kImpact);
    double worst = 0.0;
    for (const auto& st : r.event_states) {
      if (std::find(impacts.begin(), impacts.end(), st.t) == impacts.end()) continue;
      worst = std::max(worst, std::abs(std::abs(st.v_before[2]) - omega) / omega);
      omega *= ratio;
    }
    return worst;
  };
  return s;
}

Scenario plank_box() {
  model::PlankBoxParameters p;
  p.friction = 0.8;
  Scenario s;
  s.system = std::make_shared<model::PlankBoxSystem<double>>(p);
  double phi = 0.0;  // plank at rest: k φ + m_P g (L_P/2) cos φ = 0
  for (int i = 0; i < 50; ++i)
    phi -= (p.plank_stiffness * phi + p.plank_mass * g * p.plank_length / 2 * std::cos(phi)) /
           (p.plank_stiffness - p.plank_mass * g * p.plank_length / 2 * std::sin(phi));
  // The box tilted by 3° against the plank lands on C_L first; the rotation about C_L, with
  // the plank swinging, has no closed form, so the error of the C_R impact time is measured
  // against a run at tolerance 1e-13 (computed once).
  const double tilt = 3.0 * M_PI / 180.0, theta = phi + tilt;
  const Eigen::Vector2d e1(std::cos(phi), std::sin(phi)), e2(-std::sin(phi), std::cos(phi));
  const double gap = 0.01;
  const double lift = p.box_length / 2 * std::sin(tilt) + p.box_height / 2 * std::cos(tilt);
  const Eigen::Vector2d centre = 0.5 * e1 + (p.plank_thickness / 2 + gap + lift) * e2;
  s.q0 = Eigen::Vector4d(centre.x(), centre.y(), theta, phi);
  s.v0 = Eigen::Vector4d(0, -1.0, 0, 0);
  s.duration = 0.5;
  const auto second_impact = [](const EventDrivenResult& r) {
    const auto t = event_times(r, EventKind::kImpact);
    return r.succeeded() && t.size() >= 2 ? t[1] : std::nan("");
  };
  EventDrivenOptions tight;
  tight.relative_tolerance = tight.absolute_tolerance = 1e-13;
  const double reference =
      second_impact(EventDrivenIntegrator(*s.system, tight).simulate(s.q0, s.v0, {}, s.duration));
  s.error = [=](const EventDrivenResult& r) {
    return std::abs(second_impact(r) - reference) / reference;
  };
  return s;
}

Scenario sphere_spin() {
  const double r = 0.1, mu = 0.3;
  model::spatial::SpatialSystemSpec spec;
  model::BodySpec ball;
  ball.name = "ball";
  ball.shape = model::ShapeKind::kSphere;
  ball.radius = r;
  ball.mass = 1.0;
  ball.position = Eigen::Vector3d(0, 0, r);
  spec.bodies.push_back(ball);
  model::StaticPlaneSpec floor;
  floor.normal = Eigen::Vector3d::UnitZ();
  spec.planes.push_back(floor);
  spec.material.friction = mu;
  spec.gravity = g;
  Scenario s;
  s.system = std::make_shared<model::spatial::SpatialRigidBodySystem<double>>(spec);
  const Eigen::Vector3d v0(1.0, 0.5, 0.0), w0(4.0, -6.0, 3.0);
  s.q0.resize(7);
  s.q0 << 0, 0, r, 1, 0, 0, 0;
  s.v0.resize(6);
  s.v0 << v0, w0;
  const Eigen::Vector3d c0 = v0 + w0.cross(Eigen::Vector3d(0, 0, -r));
  const double t_star = 2 * c0.norm() / (7 * mu * g);
  s.duration = 2 * t_star;
  s.error = [=](const EventDrivenResult& result) {
    const auto t = event_times(result, EventKind::kSlipToStick);
    return result.succeeded() && !t.empty() ? std::abs(t[0] - t_star) / t_star : std::nan("");
  };
  return s;
}

void run_event_scenario(benchmark::State& state, Scenario (*make)(),
                        const EventDrivenOptions& options) {
  const Scenario s = make();
  const EventDrivenIntegrator integrator(*s.system, options);
  double seconds = 0.0;
  long events = 0, steps = 0, rhs = 0, roots = 0, runs = 0;
  for (auto _ : state) {
    // CPU time of this process, so that the per-event figures do not count other load.
    const std::clock_t start = std::clock();
    const auto result = integrator.simulate(s.q0, s.v0, s.input, s.duration);
    seconds += static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    if (!result.succeeded()) {
      state.SkipWithError(result.message.c_str());
      return;
    }
    events += static_cast<long>(result.events.size());
    steps += result.summary.steps;
    rhs += result.summary.rhs_evaluations;
    roots += result.summary.root_evaluations;
    ++runs;
  }
  const double n = static_cast<double>(runs);
  state.counters["events"] = static_cast<double>(events) / n;
  state.counters["cvode_steps"] = static_cast<double>(steps) / n;
  state.counters["rhs_evaluations"] = static_cast<double>(rhs) / n;
  state.counters["root_evaluations"] = static_cast<double>(roots) / n;
  state.counters["us_per_event"] = events ? 1e6 * seconds / static_cast<double>(events) : 0.0;
  state.counters["ms_per_simulated_second"] = 1e3 * seconds / (n * s.duration);
}

void BM_EventScenario(benchmark::State& state, Scenario (*make)()) {
  run_event_scenario(state, make, {});
}

// The same with the two options that trade bit-for-bit agreement with CVODE's own startup and
// rootfinding for speed (event_driven_options.hpp): growth lifted at order 2, roots located on
// the dense output.
void BM_EventScenarioFastRestart(benchmark::State& state, Scenario (*make)()) {
  EventDrivenOptions options;
  options.startup_order = 2;
  options.dense_output_root_search = true;
  run_event_scenario(state, make, options);
}

void BM_EventScenarioNoSamples(benchmark::State& state, Scenario (*make)()) {
  EventDrivenOptions options;
  options.output_interval = 0.0;
  run_event_scenario(state, make, options);
}

void BM_EventScenarioErk(benchmark::State& state, Scenario (*make)()) {
  EventDrivenOptions options;
  options.method = FlowMethod::kErk;
  run_event_scenario(state, make, options);
}

void BM_EventScenarioOwnErk(benchmark::State& state, Scenario (*make)()) {
  EventDrivenOptions options;
  options.method = FlowMethod::kOwnErk;
  run_event_scenario(state, make, options);
}

void BM_EventScenarioErkDenseRoots(benchmark::State& state, Scenario (*make)()) {
  EventDrivenOptions options;
  options.method = FlowMethod::kErk;
  options.dense_output_root_search = true;
  run_event_scenario(state, make, options);
}

// CVODE (default, fast restart), ERK and own_erk run after one another in every iteration, so
// that the load of a shared machine falls on all four alike: process CPU time per event of each,
// the ratios to CVODE's default, and each one's integrator steps and guard evaluations per run.
void BM_EventScenarioPaired(benchmark::State& state, Scenario (*make)()) {
  const Scenario s = make();
  EventDrivenOptions fast, erk, own_erk;
  fast.startup_order = 2;
  fast.dense_output_root_search = true;
  erk.method = FlowMethod::kErk;
  own_erk.method = FlowMethod::kOwnErk;
  const std::vector<std::pair<std::string, EventDrivenOptions>> variants = {
      {"cvode", EventDrivenOptions{}}, {"fast", fast}, {"erk", erk}, {"own_erk", own_erk}};
  std::vector<EventDrivenIntegrator> integrators;
  for (const auto& variant : variants) integrators.emplace_back(*s.system, variant.second);
  std::vector<double> seconds(variants.size(), 0.0);
  std::vector<long> events(variants.size(), 0), steps(variants.size(), 0),
      roots(variants.size(), 0);
  long runs = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < variants.size(); ++i) {
      const std::clock_t start = std::clock();
      const auto result = integrators[i].simulate(s.q0, s.v0, s.input, s.duration);
      seconds[i] += static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
      if (!result.succeeded()) {
        state.SkipWithError((variants[i].first + ": " + result.message).c_str());
        return;
      }
      events[i] += static_cast<long>(result.events.size());
      steps[i] += result.summary.steps;
      roots[i] += result.summary.root_evaluations;
    }
    ++runs;
  }
  const double n = static_cast<double>(runs);
  std::vector<double> per_event(variants.size(), 0.0);
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const std::string& name = variants[i].first;
    per_event[i] = events[i] ? 1e6 * seconds[i] / static_cast<double>(events[i]) : 0.0;
    state.counters[name + "_us_per_event"] = per_event[i];
    state.counters[name + "_events"] = static_cast<double>(events[i]) / n;
    state.counters[name + "_steps"] = static_cast<double>(steps[i]) / n;
    state.counters[name + "_root_evaluations"] = static_cast<double>(roots[i]) / n;
  }
  state.counters["fast_over_cvode"] = per_event[1] / per_event[0];
  state.counters["erk_over_cvode"] = per_event[2] / per_event[0];
  state.counters["own_erk_over_cvode"] = per_event[3] / per_event[0];
  state.counters["own_erk_over_erk"] = per_event[3] / per_event[2];
}

void run_work_precision(benchmark::State& state, Scenario (*make)(), EventDrivenOptions options) {
  const Scenario s = make();
  options.relative_tolerance = options.absolute_tolerance =
      std::pow(10.0, -static_cast<double>(state.range(0)));
  const EventDrivenIntegrator integrator(*s.system, options);
  double error = 0.0;
  long rhs = 0, runs = 0;
  for (auto _ : state) {
    const auto result = integrator.simulate(s.q0, s.v0, s.input, s.duration);
    if (!result.succeeded()) {
      state.SkipWithError(result.message.c_str());
      return;
    }
    error = s.error(result);
    rhs += result.summary.rhs_evaluations;
    ++runs;
  }
  state.counters["tolerance"] = options.relative_tolerance;
  state.counters["error"] = error;
  state.counters["rhs_evaluations"] = static_cast<double>(rhs) / static_cast<double>(runs);
}

void BM_EventWorkPrecision(benchmark::State& state, Scenario (*make)()) {
  run_work_precision(state, make, {});
}

void BM_EventWorkPrecisionStartup(benchmark::State& state, Scenario (*make)()) {
  EventDrivenOptions options;
  options.startup_order = 2;
  run_work_precision(state, make, options);
}

void BM_EventWorkPrecisionDenseRoots(benchmark::State& state, Scenario (*make)()) {
  EventDrivenOptions options;
  options.dense_output_root_search = true;
  run_work_precision(state, make, options);
}

void BM_EventWorkPrecisionOwnErk(benchmark::State& state, Scenario (*make)()) {
  EventDrivenOptions options;
  options.method = FlowMethod::kOwnErk;
  run_work_precision(state, make, options);
}

}  // namespace

BENCHMARK_CAPTURE(BM_EventScenario, bouncing_ball, bouncing_ball)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenario, sliding_block, sliding_block)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenario, incline_push, incline_push)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenario, rocking_block, rocking_block)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenario, plank_box, plank_box)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenario, sphere_spin, sphere_spin)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioNoSamples, bouncing_ball, bouncing_ball)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioNoSamples, rocking_block, rocking_block)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioNoSamples, plank_box, plank_box)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioFastRestart, bouncing_ball, bouncing_ball)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioFastRestart, rocking_block, rocking_block)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioFastRestart, plank_box, plank_box)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioErk, bouncing_ball, bouncing_ball)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioErk, sliding_block, sliding_block)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioErk, incline_push, incline_push)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioErk, rocking_block, rocking_block)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioErk, plank_box, plank_box)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioErk, sphere_spin, sphere_spin)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioErkDenseRoots, bouncing_ball, bouncing_ball)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioErkDenseRoots, rocking_block, rocking_block)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioErkDenseRoots, plank_box, plank_box)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioOwnErk, bouncing_ball, bouncing_ball)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioOwnErk, sliding_block, sliding_block)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioOwnErk, incline_push, incline_push)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioOwnErk, rocking_block, rocking_block)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioOwnErk, plank_box, plank_box)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioOwnErk, sphere_spin, sphere_spin)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioPaired, bouncing_ball, bouncing_ball)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioPaired, rocking_block, rocking_block)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventScenarioPaired, plank_box, plank_box)->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_EventWorkPrecision, bouncing_ball, bouncing_ball)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecision, sliding_block, sliding_block)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecision, incline_push, incline_push)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecision, rocking_block, rocking_block)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecision, plank_box, plank_box)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_EventWorkPrecision, sphere_spin, sphere_spin)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionStartup, bouncing_ball, bouncing_ball)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionDenseRoots, bouncing_ball, bouncing_ball)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionStartup, sliding_block, sliding_block)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionDenseRoots, sliding_block, sliding_block)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionStartup, incline_push, incline_push)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionDenseRoots, incline_push, incline_push)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionStartup, rocking_block, rocking_block)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionDenseRoots, rocking_block, rocking_block)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionStartup, plank_box, plank_box)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionDenseRoots, plank_box, plank_box)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionStartup, sphere_spin, sphere_spin)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionDenseRoots, sphere_spin, sphere_spin)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionOwnErk, bouncing_ball, bouncing_ball)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionOwnErk, rocking_block, rocking_block)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionOwnErk, plank_box, plank_box)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionOwnErk, sliding_block, sliding_block)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionOwnErk, incline_push, incline_push)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EventWorkPrecisionOwnErk, sphere_spin, sphere_spin)
    ->DenseRange(4, 12, 1)
    ->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  return impactbench::bench::run_registered_benchmarks(argc, argv, [] {});
}
