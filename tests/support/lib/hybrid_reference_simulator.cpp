#include "tests/support/lib/hybrid_reference_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "tests/support/lib/rk4.hpp"

namespace impactbench::test_support {
namespace {

using sensitivity::ContactPhase;
using sensitivity::GuardKind;
using sensitivity::HybridMode;
using sensitivity::MicroEvent;

std::vector<MicroEvent> candidate_events(const HybridMode& mode, const HybridMode& impact_phase) {
  std::vector<MicroEvent> out;
  for (int i = 0; i < static_cast<int>(mode.size()); ++i) {
    switch (mode[i]) {
      case ContactPhase::kOpen:
        out.push_back({i, GuardKind::kImpact, impact_phase[i]});
        break;
      case ContactPhase::kSlipPositive:
      case ContactPhase::kSlipNegative:
        out.push_back({i, GuardKind::kLiftOff, ContactPhase::kOpen});
        out.push_back({i, GuardKind::kSlipToStick, ContactPhase::kStick});
        break;
      case ContactPhase::kStick:
        out.push_back({i, GuardKind::kLiftOff, ContactPhase::kOpen});
        out.push_back({i, GuardKind::kStickToSlip, ContactPhase::kSlipPositive});
        out.push_back({i, GuardKind::kStickToSlip, ContactPhase::kSlipNegative});
        break;
    }
  }
  return out;
}

Eigen::VectorXd input_at(const sensitivity::InputFunction& u, double t, int m) {
  return u ? u(t) : Eigen::VectorXd::Zero(m);
}

/// The RK4 increment x(t + h) − x(t).
Eigen::VectorXd rk4_increment(const sensitivity::MechanicalHybridModel& model,
                              const HybridMode& mode, const sensitivity::InputFunction& u, double t,
                              const Eigen::VectorXd& x, double h) {
  const int m = model.input_size();
  return test_support::rk4_increment(
      [&](double ts, const Eigen::VectorXd& xs) {
        return Eigen::VectorXd(model.flow(mode, xs, input_at(u, ts, m)));
      },
      t, x, h);
}

Eigen::VectorXd rk4(const sensitivity::MechanicalHybridModel& model, const HybridMode& mode,
                    const sensitivity::InputFunction& u, double t, const Eigen::VectorXd& x,
                    double h) {
  return x + rk4_increment(model, mode, u, t, x, h);
}

/// x += dx with Kahan compensation: the round-off of thousands of steps would otherwise set a
/// noise floor of ~1e-14 under the O(ε²) errors the tests measure.
void compensated_add(Eigen::VectorXd& x, Eigen::VectorXd& carry, const Eigen::VectorXd& dx) {
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double y = dx(i) - carry(i);
    const double sum = x(i) + y;
    carry(i) = (sum - x(i)) - y;
    x(i) = sum;
  }
}

}  // namespace

ReferenceRun simulate_reference(const sensitivity::MechanicalHybridModel& model,
                                const HybridMode& mode0, const Eigen::VectorXd& x0,
                                const sensitivity::InputFunction& u, double t0, double t_end,
                                const std::vector<double>& sample_times,
                                const ReferenceOptions& options) {
  if (!(options.max_step > 0.0))
    throw std::invalid_argument("simulate_reference: max_step must be positive");
  if (static_cast<int>(options.impact_phase.size()) != model.num_contacts())
    throw std::invalid_argument("simulate_reference: impact_phase needs one entry per contact");
  const int m = model.input_size();
  ReferenceRun run;
  HybridMode mode = mode0;
  Eigen::VectorXd x = x0;
  Eigen::VectorXd carry = Eigen::VectorXd::Zero(x0.size());
  double t = t0;
  std::size_t next_sample = 0;
  const auto record_samples = [&] {
    while (next_sample < sample_times.size() && sample_times[next_sample] <= t) {
      run.times.push_back(sample_times[next_sample]);
      run.states.push_back(x);
      ++next_sample;
    }
  };
  record_samples();
  while (t < t_end) {
    double target = std::min(t + options.max_step, t_end);
    if (next_sample < sample_times.size()) target = std::min(target, sample_times[next_sample]);
    const double h = target - t;
    const Eigen::VectorXd dx = rk4_increment(model, mode, u, t, x, h);
    const Eigen::VectorXd x_end = x + dx;
    // Earliest guard crossing within the step.
    double h_event = h;
    const MicroEvent* fired = nullptr;
    const std::vector<MicroEvent> candidates = candidate_events(mode, options.impact_phase);
    for (const MicroEvent& event : candidates) {
      const auto guard = [&](double s) {
        const Eigen::VectorXd xs = s == 0.0 ? x : (s == h ? x_end : rk4(model, mode, u, t, x, s));
        return model.guard_value(mode, event, xs, input_at(u, t + s, m));
      };
      if (!(guard(h) < 0.0) || guard(0.0) < -1e-12) continue;
      double lo = 0.0, hi = h;
      for (int it = 0; it < 200 && hi - lo > 1e-16 * (1.0 + std::abs(t)); ++it) {
        const double mid = 0.5 * (lo + hi);
        (guard(mid) < 0.0 ? hi : lo) = mid;
      }
      if (fired == nullptr || hi < h_event) {
        h_event = hi;
        fired = &event;
      }
    }
    if (fired == nullptr) {
      compensated_add(x, carry, dx);
      t = target;
      record_samples();
      continue;
    }
    if (static_cast<int>(run.events.size()) >= options.max_events) {
      std::string last;
      for (std::size_t i = run.events.size() - 3; i < run.events.size(); ++i)
        last += " t=" + std::to_string(run.events[i].time) + " " + to_string(run.events[i].event);
      throw std::runtime_error("simulate_reference: more than " +
                               std::to_string(options.max_events) + " events; last:" + last);
    }
    const Eigen::VectorXd x_start = x;
    const double t_start = t;
    compensated_add(x, carry, rk4_increment(model, mode, u, t, x, h_event));
    t += h_event;
    carry.setZero();
    // Guards of the same kind and target phase that vanish together with the fired one (relative
    // to their change over one max_step) switch with it.
    std::vector<MicroEvent> together{*fired};
    if (fired->kind != GuardKind::kImpact)
      for (const MicroEvent& event : candidates) {
        if (event.contact == fired->contact || event.kind != fired->kind ||
            event.phase_after != fired->phase_after)
          continue;
        const auto guard_at = [&](double time, const Eigen::VectorXd& state) {
          return model.guard_value(mode, event, state, input_at(u, time, m));
        };
        const double rate = std::abs(guard_at(t_start + h, x_end) - guard_at(t_start, x_start)) / h;
        if (guard_at(t, x) <= 1e-8 * rate * options.max_step) together.push_back(event);
      }
    for (const MicroEvent& event : together) {
      ReferenceEvent record;
      record.time = t;
      record.event = event;
      record.mode_before = mode;
      record.x_minus = x;
      x = model.reset(mode, event, x);
      mode = sensitivity::apply_event(mode, event);
      record.mode_after = mode;
      record.x_plus = x;
      run.events.push_back(std::move(record));
    }
  }
  run.final_state = x;
  run.final_mode = mode;
  return run;
}

Eigen::VectorXd flow_in_mode(const sensitivity::MechanicalHybridModel& model,
                             const HybridMode& mode, const sensitivity::InputFunction& u,
                             double t_from, const Eigen::VectorXd& x_from, double t_to,
                             double max_step) {
  if (!(max_step > 0.0)) throw std::invalid_argument("flow_in_mode: max_step must be positive");
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(t_to - t_from) / max_step)));
  const double h = (t_to - t_from) / steps;
  Eigen::VectorXd x = x_from;
  for (int k = 0; k < steps; ++k) x = rk4(model, mode, u, t_from + k * h, x, h);
  return x;
}

sensitivity::NominalTrajectory nominal_from_run(const ReferenceRun& run, const HybridMode& mode0,
                                                const Eigen::VectorXd& x0,
                                                const sensitivity::InputFunction& u,
                                                const sensitivity::InputFunction& u_rate, double t0,
                                                double t_end, double simultaneity) {
  sensitivity::NominalTrajectory nominal;
  nominal.t_begin = t0;
  nominal.t_end = t_end;
  nominal.x0 = x0;
  nominal.mode0 = mode0;
  nominal.input = u;
  nominal.input_rate = u_rate;
  for (const ReferenceEvent& e : run.events) {
    if (!nominal.events.empty() && e.time - nominal.events.back().time <= simultaneity)
      nominal.events.back().micro_events.push_back(e.event);
    else
      nominal.events.push_back({e.time, {e.event}, std::nullopt});
  }
  return nominal;
}

}  // namespace impactbench::test_support
