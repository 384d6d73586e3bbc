#pragma once
// The ε-convergence check of the sensitivity acceptance tests: the first-order prediction
// α(t) + ε z(t) of a perturbed trajectory (initial state α(t0) + ε z0, input μ + ε v) must have
// an error O(ε²) away from the event times, so that error(ε) / error(ε/2) → 4.
#include <random>
#include <vector>

#include <Eigen/Core>

#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/test_utilities/hybrid_reference_simulator.hpp"

namespace impactbench::test_utilities {

struct PerturbationDirection {
  Eigen::VectorXd z0;
  Eigen::VectorXd v0, v1;  ///< v(t) = v0 + v1 t
  sensitivity::InputFunction input() const;
};

/// A scenario's nominal with everything needed to re-simulate perturbations.
struct ConvergenceSetup {
  const sensitivity::MechanicalHybridModel* model = nullptr;
  sensitivity::HybridMode mode0;
  Eigen::VectorXd x0;
  sensitivity::InputFunction input, input_rate;
  double t0 = 0.0, t_end = 1.0;
  ReferenceOptions options;
};

/// `count` equally spaced times in [t0, t_end] (end points included), dropping those within
/// `margin` of an event time.
std::vector<double> sample_times_away_from(double t0, double t_end, int count,
                                           const std::vector<double>& event_times, double margin);

/// A random unit direction: z0 in the null space of the mode's constraint rows at (x0, mode0)
/// (so the closed contacts stay closed), v0, v1 Gaussian, all scaled to unit norm together.
/// `input_weight` 0 gives v = 0.
PerturbationDirection random_direction(const ConvergenceSetup& setup, std::mt19937& rng,
                                       double input_weight = 1.0);

/// max over the times of ‖x_ε(t) − α(t) − ε z(t)‖∞ for each ε. Throws std::runtime_error if a
/// perturbed run's event count differs from the nominal's (ε too large for the local picture).
std::vector<double> prediction_errors(const ConvergenceSetup& setup, const ReferenceRun& nominal,
                                      const std::vector<Eigen::VectorXd>& z,
                                      const PerturbationDirection& direction,
                                      const std::vector<double>& epsilons);

/// ratio[i] = error(ε_i) / error(ε_i / 2) for ε_i in `epsilons` (runs 2 × epsilons.size()).
std::vector<double> error_ratios(const ConvergenceSetup& setup, const ReferenceRun& nominal,
                                 const sensitivity::TrajectorySensitivity& sensitivity,
                                 const PerturbationDirection& direction,
                                 const std::vector<double>& epsilons);

}  // namespace impactbench::test_utilities
