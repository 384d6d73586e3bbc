#pragma once
// The ε-convergence check of the sensitivity acceptance tests: the first-order prediction
// α(t) + ε z(t) of a perturbed trajectory (initial state α(t0) + ε z0, input μ + ε v) must have
// an error O(ε²), so that error(ε) / error(ε/2) → 4.
//
// Times between a nominal and a perturbed event (reference spreading). Away from events the
// nominal α, z and the perturbed run are in the same mode. Between the nominal event τ and the
// perturbed one τ_ε they are not: there the perturbed trajectory is replaced by its extension in
// the nominal's mode at that time — its pre-event mode's flow continued past τ_ε when the nominal
// is still before τ, its post-event mode's flow continued backwards from τ_ε when the nominal is
// already past τ — so that every sample compares like with like. The jump gain is exactly the
// statement that these extended trajectories differ from α⁻ + ε z⁻ and α⁺ + ε z⁺ by O(ε²).
// For macro events (several micro events near τ) the extension starts from the perturbed's
// first micro event (pre) or last micro event (post).
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/support/lib/hybrid_reference_simulator.hpp"

namespace impactbench::test_support {

struct PerturbationDirection {
  Eigen::VectorXd z0;
  Eigen::VectorXd v0, v1;  ///< v(t) = v0 + v1 t
  sensitivity::InputFunction input() const;
};

/// A perturbed run from x0 under input u, with the states at `times` and its events (each with
/// pre/post-event states and modes, as simulate_reference gives them).
using PerturbedRunner =
    std::function<ReferenceRun(const Eigen::VectorXd& x0, const sensitivity::InputFunction& u,
                               const std::vector<double>& times)>;

/// A scenario's nominal with everything needed to re-simulate perturbations.
struct ConvergenceSetup {
  const sensitivity::MechanicalHybridModel* model = nullptr;
  sensitivity::HybridMode mode0;
  Eigen::VectorXd x0;
  sensitivity::InputFunction input, input_rate;
  double t0 = 0.0, t_end = 1.0;
  ReferenceOptions options;
  double simultaneity = 1e-9;  ///< nominal events closer than this form one macro event [s]
  PerturbedRunner runner;      ///< empty: simulate_reference with `options`
};

/// `count` equally spaced times in [t0, t_end] (end points included) and, around every event
/// time τ, probes τ ± d for d = 1e-7, 1e-6, ..., 1e-3 s inside (t0, t_end) — the samples that fall
/// between a nominal and a perturbed event for ε = 1e-3 ... 5e-6. Grid points within 1e-12 s of
/// an event are dropped (at the instant itself pre- and post-event values differ). Sorted.
std::vector<double> sample_times_with_event_probes(double t0, double t_end, int count,
                                                   const std::vector<double>& event_times);

/// The nominal run of `setup` sampled by sample_times_with_event_probes (a first run finds the
/// event times).
ReferenceRun nominal_run_with_event_probes(const ConvergenceSetup& setup, int count);

/// The sensitivity module's nominal for a reference run of `setup`.
sensitivity::NominalTrajectory nominal_of(const ConvergenceSetup& setup, const ReferenceRun& run);

/// A random unit direction: z0 in the null space of the mode's constraint rows at (x0, mode0)
/// (so the closed contacts stay closed), v0, v1 Gaussian, all scaled to unit norm together.
/// `input_weight` 0 gives v = 0.
PerturbationDirection random_direction(const ConvergenceSetup& setup, std::mt19937& rng,
                                       double input_weight = 1.0);

/// How prediction_errors compares a perturbed state with the prediction: kLikeWithLike extends
/// the perturbed trajectory into the nominal's mode between events (header comment); kRaw takes
/// the perturbed run's state as it is (only for the control experiment showing that the samples
/// near events do fall between the nominal and perturbed events).
enum class Comparison { kLikeWithLike, kRaw };

/// max over the nominal's sample times of ‖x_ε(t) − α(t) − ε z(t)‖∞ for each ε. Throws
/// std::runtime_error if a perturbed run's event count differs from the nominal's (ε too large
/// for the local picture).
std::vector<double> prediction_errors(const ConvergenceSetup& setup, const ReferenceRun& nominal,
                                      const std::vector<Eigen::VectorXd>& z,
                                      const PerturbationDirection& direction,
                                      const std::vector<double>& epsilons,
                                      Comparison comparison = Comparison::kLikeWithLike);

struct RatioRange {
  double min = 0.0, max = 0.0;  ///< over the measured ratios
  int measured = 0;             ///< (direction, ε) pairs with a ratio
  int below_floor = 0;          ///< pairs whose error at ε/2 is below the round-off floor
};

/// The acceptance check shared by every scenario: for each direction and ε = 1e-3, 1e-4, 1e-5,
/// the ratio error(ε)/error(ε/2) must lie in [3, 5] (gtest EXPECTs naming the direction and ε).
/// Where the error at ε/2 is below the round-off floor 100 ε_mach max‖α‖∞ the ratio is noise;
/// there both errors must instead lie below 2 C ε² + floor, C = error/ε² at ε = 5e-4 (an O(ε)
/// error fails this by orders of magnitude). Prints and returns the measured range and counts.
RatioRange expect_second_order(const ConvergenceSetup& setup, const ReferenceRun& nominal,
                               const sensitivity::TrajectorySensitivity& sensitivity,
                               const std::vector<PerturbationDirection>& directions,
                               const std::string& label);

}  // namespace impactbench::test_support
