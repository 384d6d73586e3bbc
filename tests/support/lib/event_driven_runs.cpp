#include "tests/support/lib/event_driven_runs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "lib/sensitivity/event_driven_nominal.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/support/lib/sensitivity_convergence.hpp"

namespace impactbench::test_support {

namespace ed = engines::event_driven;
using sensitivity::HybridMode;
using sensitivity::InputFunction;
using sensitivity::MicroEvent;
using sensitivity::NominalEvent;
using sensitivity::NominalTrajectory;

ed::EventDrivenOptions tight_event_options() {
  ed::EventDrivenOptions o;
  o.relative_tolerance = 1e-12;
  o.absolute_tolerance = 1e-12;
  o.output_interval = 0.005;
  return o;
}

ed::EventDrivenResult EventRuns::run(const Eigen::VectorXd& x0, const InputFunction& u) const {
  const ed::EventDrivenIntegrator integrator(system_, options);
  const int nq = system_.num_positions();
  const Eigen::VectorXd x = initial_projection ? initial_projection(x0) : x0;
  return integrator.simulate(x.head(nq), x.tail(x.size() - nq), u, end_);
}

std::map<long, Eigen::VectorXd> EventRuns::grid_states(const ed::EventDrivenResult& r) {
  std::map<long, Eigen::VectorXd> out;
  for (const ed::SampleView& s : r.samples) {
    const double k = std::round(s.t / 0.005);
    if (std::abs(s.t - 0.005 * k) < 1e-12) {
      Eigen::VectorXd x(s.q.size() + s.v.size());
      x << s.q, s.v;
      out[static_cast<long>(k)] = x;
    }
  }
  return out;
}

ReferenceRun EventRuns::as_reference_run(const ed::EventDrivenResult& r, const InputFunction& u,
                                         const std::vector<double>& times) const {
  ReferenceRun out;
  const auto grid = grid_states(r);
  for (const double t : times) {
    out.times.push_back(t);
    out.states.push_back(grid.at(std::lround(t / 0.005)));
  }
  const NominalTrajectory n = sensitivity::nominal_from_event_run(model_, system_, r, u, {}, end_);
  HybridMode mode = n.mode0;
  for (const NominalEvent& e : n.events) {
    const auto first = std::find_if(r.event_states.begin(), r.event_states.end(),
                                    [&](const ed::EventState& s) { return s.t == e.time; });
    Eigen::VectorXd x_minus(first->q.size() + first->v_before.size());
    x_minus << first->q, first->v_before;
    for (const MicroEvent& me : e.micro_events) {
      ReferenceEvent re;
      re.time = e.time;
      re.event = me;
      re.mode_before = mode;
      mode = apply_event(mode, me);
      re.mode_after = mode;
      re.x_minus = x_minus;   // of the instant (only the first micro event's is read)
      re.x_plus = *e.x_plus;  // of the instant (only the last micro event's is read)
      out.events.push_back(re);
    }
  }
  return out;
}

ConvergenceSetup EventRuns::setup_for(const Eigen::VectorXd& x0,
                                      const NominalTrajectory& nominal) const {
  ConvergenceSetup setup;
  setup.model = &model_;
  setup.mode0 = nominal.mode0;
  setup.x0 = x0;
  setup.input = input;
  setup.input_rate = input_rate;
  setup.t_end = end_;
  setup.runner = [this](const Eigen::VectorXd& x, const InputFunction& u,
                        const std::vector<double>& at) {
    const ed::EventDrivenResult r = run(x, u);
    if (!r.succeeded()) throw std::runtime_error("perturbed event-driven run: " + r.message);
    return as_reference_run(r, u, at);
  };
  return setup;
}

NominalTrajectory EventRuns::nominal_from(const Eigen::VectorXd& x0) const {
  const ed::EventDrivenResult nominal_run = run(x0, input);
  if (!nominal_run.succeeded())
    throw std::runtime_error("nominal event-driven run: " + nominal_run.message);
  return sensitivity::nominal_from_event_run(model_, system_, nominal_run, input, input_rate, end_);
}

std::vector<PerturbationDirection> EventRuns::random_directions(const Eigen::VectorXd& x0,
                                                                unsigned seed) const {
  const ConvergenceSetup setup = setup_for(x0, nominal_from(x0));
  std::mt19937 rng(seed);
  std::vector<PerturbationDirection> list;
  for (int d = 0; d < directions; ++d) list.push_back(random_direction(setup, rng));
  return list;
}

void EventRuns::expect_second_order_from(const Eigen::VectorXd& x0, unsigned seed,
                                         const char* label) const {
  expect_second_order_along(x0, random_directions(x0, seed), label);
}

void EventRuns::expect_second_order_along(const Eigen::VectorXd& x0,
                                          const std::vector<PerturbationDirection>& list,
                                          const char* label) const {
  const ed::EventDrivenResult nominal_run = run(x0, input);
  ASSERT_TRUE(nominal_run.succeeded()) << nominal_run.message;
  const NominalTrajectory nominal =
      sensitivity::nominal_from_event_run(model_, system_, nominal_run, input, input_rate, end_);
  const sensitivity::TrajectorySensitivity sensitivity(model_, nominal);
  std::vector<double> times;
  for (const auto& [k, x] : grid_states(nominal_run)) times.push_back(0.005 * k);
  const ReferenceRun nominal_samples = as_reference_run(nominal_run, input, times);
  expect_second_order(setup_for(x0, nominal), nominal_samples, sensitivity, list, label);
}

}  // namespace impactbench::test_support
