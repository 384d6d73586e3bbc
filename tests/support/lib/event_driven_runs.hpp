#pragma once
// Runs of the event-driven integrator (lib/engines/event_driven) read as the sensitivity ε-tests
// read runs: output on a 0.005 s grid, one reference event per micro event of the run's nominal
// (nominal_from_event_run), and the ε² check of sensitivity_convergence.hpp on them. Shared by
// the planar and spatial sensitivity tests.
#include <functional>
#include <map>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/nominal_trajectory.hpp"
#include "tests/support/lib/hybrid_reference_simulator.hpp"
#include "tests/support/lib/sensitivity_convergence.hpp"

namespace impactbench::test_support {

/// Tolerance 1e-12 (relative and absolute), output every 0.005 s.
engines::event_driven::EventDrivenOptions tight_event_options();

class EventRuns {
 public:
  EventRuns(const model::LagrangianSystem<double>& system,
            const sensitivity::MechanicalHybridModel& model, double end)
      : system_(system), model_(model), end_(end) {}

  /// Applied to every initial state before it is run (identity when empty).
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> initial_projection;
  engines::event_driven::EventDrivenOptions options = tight_event_options();
  /// Perturbation directions per ε-test.
  int directions = 20;
  /// The nominal input u(t) and its rate (empty: none).
  sensitivity::InputFunction input, input_rate;

  engines::event_driven::EventDrivenResult run(const Eigen::VectorXd& x0,
                                               const sensitivity::InputFunction& u) const;
  /// State at each grid time k·0.005 (samples on the grid only).
  static std::map<long, Eigen::VectorXd> grid_states(
      const engines::event_driven::EventDrivenResult& r);
  /// An event-driven run as the ε-test reads runs: states at `times` (grid points), one event
  /// per micro event with the instant's pre-impact state (q, v_before) and post-event state.
  ReferenceRun as_reference_run(const engines::event_driven::EventDrivenResult& r,
                                const sensitivity::InputFunction& u,
                                const std::vector<double>& times) const;
  /// The ε-test of the reference-simulator cases, on runs of the event-driven integrator: the
  /// samples are its output grid (every 0.005 s, all kept), each run's events come from
  /// nominal_from_event_run, so grid points between the nominal and a perturbed event are
  /// compared on the perturbed trajectory extended across its event (reference spreading).
  void expect_second_order_from(const Eigen::VectorXd& x0, unsigned seed, const char* label) const;
  /// The same test along given directions (e.g. split by the cone they select).
  void expect_second_order_along(const Eigen::VectorXd& x0,
                                 const std::vector<PerturbationDirection>& list,
                                 const char* label) const;
  /// The `directions` random unit directions expect_second_order_from(x0, seed, ...) uses.
  std::vector<PerturbationDirection> random_directions(const Eigen::VectorXd& x0,
                                                       unsigned seed) const;
  /// The nominal of the run from x0 (throws std::runtime_error if the run fails).
  sensitivity::NominalTrajectory nominal_from(const Eigen::VectorXd& x0) const;

 private:
  ConvergenceSetup setup_for(const Eigen::VectorXd& x0,
                             const sensitivity::NominalTrajectory& nominal) const;

  const model::LagrangianSystem<double>& system_;
  const sensitivity::MechanicalHybridModel& model_;
  double end_;
};

}  // namespace impactbench::test_support
