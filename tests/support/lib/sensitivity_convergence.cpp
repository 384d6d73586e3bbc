#include "tests/support/lib/sensitivity_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>
#include <Eigen/LU>

namespace impactbench::test_support {
namespace {

/// The micro events of a run grouped into macro events of sizes `sizes`: index of the first
/// micro event of each group, plus one past the end.
std::vector<std::size_t> group_starts(const std::vector<std::size_t>& sizes) {
  std::vector<std::size_t> starts{0};
  for (const std::size_t n : sizes) starts.push_back(starts.back() + n);
  return starts;
}

/// Sizes of the nominal's macro events (events closer than `simultaneity` merged).
std::vector<std::size_t> macro_sizes(const ReferenceRun& run, double simultaneity) {
  std::vector<std::size_t> sizes;
  for (std::size_t i = 0; i < run.events.size(); ++i) {
    if (i > 0 && run.events[i].time - run.events[i - 1].time <= simultaneity)
      ++sizes.back();
    else
      sizes.push_back(1);
  }
  return sizes;
}

/// The perturbed state at `t` in the mode the nominal is in at t (header comment): `segment` is
/// the number of nominal macro events before t.
Eigen::VectorXd like_with_like(const ConvergenceSetup& setup, const ReferenceRun& perturbed,
                               const std::vector<std::size_t>& starts, std::size_t segment,
                               const sensitivity::InputFunction& input, double t,
                               const Eigen::VectorXd& recorded) {
  if (segment > 0) {
    const ReferenceEvent& last = perturbed.events[starts[segment] - 1];
    if (last.time >= t)  // perturbed still before its event: its post-event flow, backwards
      return flow_in_mode(*setup.model, last.mode_after, input, last.time, last.x_plus, t,
                          setup.options.max_step);
  }
  if (segment + 1 < starts.size()) {
    const ReferenceEvent& first = perturbed.events[starts[segment]];
    if (first.time <= t)  // perturbed already past its event: its pre-event flow, forwards
      return flow_in_mode(*setup.model, first.mode_before, input, first.time, first.x_minus, t,
                          setup.options.max_step);
  }
  return recorded;
}

}  // namespace

sensitivity::InputFunction PerturbationDirection::input() const {
  const Eigen::VectorXd a = v0, b = v1;
  return [a, b](double t) -> Eigen::VectorXd { return a + t * b; };
}

std::vector<double> sample_times_with_event_probes(double t0, double t_end, int count,
                                                   const std::vector<double>& event_times) {
  std::vector<double> out;
  for (int i = 0; i < count; ++i) {
    const double t = t0 + (t_end - t0) * i / (count - 1);
    const bool at_event = std::any_of(event_times.begin(), event_times.end(),
                                      [&](double te) { return std::abs(t - te) < 1e-12; });
    if (!at_event) out.push_back(t);
  }
  for (const double te : event_times)
    for (double d = 1e-7; d < 2e-3; d *= 10)
      for (const double t : {te - d, te + d})
        if (t > t0 && t < t_end) out.push_back(t);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

ReferenceRun nominal_run_with_event_probes(const ConvergenceSetup& setup, int count) {
  const auto simulate = [&](const std::vector<double>& times) {
    return simulate_reference(*setup.model, setup.mode0, setup.x0, setup.input, setup.t0,
                              setup.t_end, times, setup.options);
  };
  std::vector<double> event_times;
  for (const ReferenceEvent& e : simulate({}).events) event_times.push_back(e.time);
  return simulate(sample_times_with_event_probes(setup.t0, setup.t_end, count, event_times));
}

sensitivity::NominalTrajectory nominal_of(const ConvergenceSetup& setup, const ReferenceRun& run) {
  return nominal_from_run(run, setup.mode0, setup.x0, setup.input, setup.input_rate, setup.t0,
                          setup.t_end, setup.simultaneity);
}

PerturbationDirection random_direction(const ConvergenceSetup& setup, std::mt19937& rng,
                                       double input_weight) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const int n = setup.model->state_size();
  const int m = setup.model->input_size();
  const Eigen::MatrixXd C = setup.model->mode_constraint_rows(setup.mode0, setup.x0);
  Eigen::MatrixXd basis = Eigen::MatrixXd::Identity(n, n);
  if (C.rows() > 0) basis = Eigen::FullPivLU<Eigen::MatrixXd>(C).kernel();
  PerturbationDirection d;
  Eigen::VectorXd coefficients(basis.cols());
  for (Eigen::Index i = 0; i < coefficients.size(); ++i) coefficients(i) = normal(rng);
  d.z0 = basis * coefficients;
  d.v0.resize(m);
  d.v1.resize(m);
  for (int j = 0; j < m; ++j) {
    d.v0(j) = input_weight * normal(rng);
    d.v1(j) = input_weight * normal(rng);
  }
  const double norm = std::sqrt(d.z0.squaredNorm() + d.v0.squaredNorm() + d.v1.squaredNorm());
  d.z0 /= norm;
  d.v0 /= norm;
  d.v1 /= norm;
  return d;
}

std::vector<double> prediction_errors(const ConvergenceSetup& setup, const ReferenceRun& nominal,
                                      const std::vector<Eigen::VectorXd>& z,
                                      const PerturbationDirection& direction,
                                      const std::vector<double>& epsilons, Comparison comparison) {
  std::vector<double> errors;
  const sensitivity::InputFunction v = direction.input();
  const std::vector<std::size_t> starts = group_starts(macro_sizes(nominal, setup.simultaneity));
  for (const double eps : epsilons) {
    const sensitivity::InputFunction perturbed_input = [&](double t) -> Eigen::VectorXd {
      const Eigen::VectorXd base =
          setup.input ? setup.input(t) : Eigen::VectorXd::Zero(setup.model->input_size());
      return base + eps * v(t);
    };
    const Eigen::VectorXd x0 = setup.x0 + eps * direction.z0;
    const ReferenceRun run =
        setup.runner ? setup.runner(x0, perturbed_input, nominal.times)
                     : simulate_reference(*setup.model, setup.mode0, x0, perturbed_input, setup.t0,
                                          setup.t_end, nominal.times, setup.options);
    if (run.events.size() != nominal.events.size())
      throw std::runtime_error("perturbed run with eps = " + std::to_string(eps) + " has " +
                               std::to_string(run.events.size()) + " events, the nominal " +
                               std::to_string(nominal.events.size()));
    double worst = 0.0;
    std::size_t segment = 0;
    for (std::size_t i = 0; i < nominal.times.size(); ++i) {
      const double t = nominal.times[i];
      while (segment + 1 < starts.size() && nominal.events[starts[segment]].time < t) ++segment;
      const Eigen::VectorXd x =
          comparison == Comparison::kRaw
              ? run.states[i]
              : like_with_like(setup, run, starts, segment, perturbed_input, t, run.states[i]);
      worst = std::max(worst, (x - nominal.states[i] - eps * z[i]).lpNorm<Eigen::Infinity>());
    }
    errors.push_back(worst);
  }
  return errors;
}

RatioRange expect_second_order(const ConvergenceSetup& setup, const ReferenceRun& nominal,
                               const sensitivity::TrajectorySensitivity& sensitivity,
                               const std::vector<PerturbationDirection>& directions,
                               const std::string& label) {
  // Round-off floor of the error measure: a few hundred ulps of the largest state entry.
  double scale = 0.0;
  for (const Eigen::VectorXd& x : nominal.states)
    scale = std::max(scale, x.lpNorm<Eigen::Infinity>());
  const double floor = 100 * std::numeric_limits<double>::epsilon() * scale;
  const std::vector<double> epsilons{1e-3, 1e-4, 1e-5};
  RatioRange range{1e300, 0.0, 0, 0};
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const PerturbationDirection& d = directions[k];
    const std::vector<Eigen::VectorXd> z = sensitivity.perturbation(d.z0, d.input(), nominal.times);
    std::vector<double> all;
    for (const double eps : epsilons) {
      all.push_back(eps);
      all.push_back(eps / 2);
    }
    const std::vector<double> errors = prediction_errors(setup, nominal, z, d, all);
    // Quadratic coefficient seen at the largest ε (the most accurate measurement).
    const double coefficient = errors[1] / (all[1] * all[1]);
    for (std::size_t i = 0; i < epsilons.size(); ++i) {
      const double e = errors[2 * i], e_half = errors[2 * i + 1];
      if (e_half >= floor) {
        const double r = e / e_half;
        EXPECT_GE(r, 3.0) << label << " direction " << k << " eps " << epsilons[i];
        EXPECT_LE(r, 5.0) << label << " direction " << k << " eps " << epsilons[i];
        range.min = std::min(range.min, r);
        range.max = std::max(range.max, r);
        ++range.measured;
      } else {
        // The O(ε²) error has sunk below round-off (a direction that is almost a symmetry of
        // the motion, e.g. a pure shift of a sliding box): no ratio can be measured, but both
        // errors must stay under the quadratic envelope of the larger ε plus the floor (an O(ε)
        // error would exceed it by orders of magnitude).
        EXPECT_LE(e, 2 * coefficient * epsilons[i] * epsilons[i] + floor)
            << label << " direction " << k << " eps " << epsilons[i];
        EXPECT_LE(e_half, 2 * coefficient * all[2 * i + 1] * all[2 * i + 1] + floor)
            << label << " direction " << k << " eps " << epsilons[i] / 2;
        ++range.below_floor;
      }
    }
  }
  EXPECT_GT(range.measured, 0) << label;
  std::cout << "[" << label << "] error ratio e(eps)/e(eps/2), eps = 1e-3..1e-5, "
            << directions.size() << " directions: " << range.min << " .. " << range.max << " ("
            << range.measured << " ratios; " << range.below_floor
            << " pairs below the round-off floor " << floor << ", checked by the envelope)\n";
  return range;
}

}  // namespace impactbench::test_support
