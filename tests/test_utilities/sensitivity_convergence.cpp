#include "tests/test_utilities/sensitivity_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

namespace impactbench::test_utilities {

sensitivity::InputFunction PerturbationDirection::input() const {
  const Eigen::VectorXd a = v0, b = v1;
  return [a, b](double t) -> Eigen::VectorXd { return a + t * b; };
}

std::vector<double> sample_times_away_from(double t0, double t_end, int count,
                                           const std::vector<double>& event_times, double margin) {
  std::vector<double> out;
  for (int i = 0; i < count; ++i) {
    const double t = t0 + (t_end - t0) * i / (count - 1);
    const bool near = std::any_of(event_times.begin(), event_times.end(),
                                  [&](double te) { return std::abs(t - te) < margin; });
    if (!near) out.push_back(t);
  }
  return out;
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
                                      const std::vector<double>& epsilons) {
  std::vector<double> errors;
  const sensitivity::InputFunction v = direction.input();
  for (const double eps : epsilons) {
    const sensitivity::InputFunction perturbed_input = [&](double t) -> Eigen::VectorXd {
      const Eigen::VectorXd base =
          setup.input ? setup.input(t) : Eigen::VectorXd::Zero(setup.model->input_size());
      return base + eps * v(t);
    };
    const ReferenceRun run =
        simulate_reference(*setup.model, setup.mode0, setup.x0 + eps * direction.z0,
                           perturbed_input, setup.t0, setup.t_end, nominal.times, setup.options);
    if (run.events.size() != nominal.events.size())
      throw std::runtime_error("perturbed run with eps = " + std::to_string(eps) + " has " +
                               std::to_string(run.events.size()) + " events, the nominal " +
                               std::to_string(nominal.events.size()));
    double worst = 0.0;
    for (std::size_t i = 0; i < nominal.times.size(); ++i)
      worst = std::max(worst,
                       (run.states[i] - nominal.states[i] - eps * z[i]).lpNorm<Eigen::Infinity>());
    errors.push_back(worst);
  }
  return errors;
}

std::vector<double> error_ratios(const ConvergenceSetup& setup, const ReferenceRun& nominal,
                                 const sensitivity::TrajectorySensitivity& sensitivity,
                                 const PerturbationDirection& direction,
                                 const std::vector<double>& epsilons) {
  const std::vector<Eigen::VectorXd> z =
      sensitivity.perturbation(direction.z0, direction.input(), nominal.times);
  std::vector<double> all;
  for (const double eps : epsilons) {
    all.push_back(eps);
    all.push_back(eps / 2);
  }
  const std::vector<double> errors = prediction_errors(setup, nominal, z, direction, all);
  std::vector<double> ratios;
  for (std::size_t i = 0; i < epsilons.size(); ++i)
    ratios.push_back(errors[2 * i] / errors[2 * i + 1]);
  return ratios;
}

}  // namespace impactbench::test_utilities
