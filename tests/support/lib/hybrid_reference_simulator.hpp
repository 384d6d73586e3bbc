#pragma once
// A small, exact-event reference simulator for the sensitivity tests, independent of the
// event-driven engine: classical RK4 on each mode's vector field (MechanicalHybridModel::flow)
// with steps that land on the requested sample times, and every guard crossing located by
// bisection on the step size of the RK4 step from the last grid point (the located state is an
// RK4 step of exactly that size, so events are as accurate as the steps themselves).
//
// Mode changes (B.3.3): open → impact (phase after given per contact in the options: open for a
// bouncing contact, a closed phase for an inelastic one); slip → lift-off (open) or slip→stick;
// stick → lift-off or stick→slip in either direction. Non-impact guards that reach zero together
// with the one that fired (|γ| below 1e-8 × its change over one max_step, e.g. the two corners
// of a sliding box stopping) switch at the same instant, as separate events with equal times.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/nominal_trajectory.hpp"

namespace impactbench::test_support {

struct ReferenceOptions {
  double max_step = 5e-4;  ///< RK4 step bound [s]
  int max_events = 50;
  /// Phase each contact takes after an impact (one entry per contact).
  sensitivity::HybridMode impact_phase;
};

struct ReferenceEvent {
  double time = 0.0;
  sensitivity::MicroEvent event;
  sensitivity::HybridMode mode_before, mode_after;
  Eigen::VectorXd x_minus, x_plus;  ///< the state just before and after this micro event
};

struct ReferenceRun {
  std::vector<double> times;            ///< the requested sample times
  std::vector<Eigen::VectorXd> states;  ///< the state at each (post-event value at an event time)
  std::vector<ReferenceEvent> events;
  Eigen::VectorXd final_state;
  sensitivity::HybridMode final_mode;
};

/// Simulates from (x0, mode0) at t0 to t_end under input u (empty: zero). Sample times must be
/// non-decreasing within [t0, t_end]. Throws std::runtime_error after max_events events.
ReferenceRun simulate_reference(const sensitivity::MechanicalHybridModel& model,
                                const sensitivity::HybridMode& mode0, const Eigen::VectorXd& x0,
                                const sensitivity::InputFunction& u, double t0, double t_end,
                                const std::vector<double>& sample_times,
                                const ReferenceOptions& options);

/// The state at t_to of the flow of `mode` from (t_from, x_from), forward or backward in time
/// (RK4 steps of at most max_step): a mode's trajectory extended past its guards.
Eigen::VectorXd flow_in_mode(const sensitivity::MechanicalHybridModel& model,
                             const sensitivity::HybridMode& mode,
                             const sensitivity::InputFunction& u, double t_from,
                             const Eigen::VectorXd& x_from, double t_to, double max_step);

/// The nominal for the sensitivity module: events closer than `simultaneity` [s] form one macro
/// event (at the first one's time).
sensitivity::NominalTrajectory nominal_from_run(const ReferenceRun& run,
                                                const sensitivity::HybridMode& mode0,
                                                const Eigen::VectorXd& x0,
                                                const sensitivity::InputFunction& u,
                                                const sensitivity::InputFunction& u_rate, double t0,
                                                double t_end, double simultaneity = 1e-9);

}  // namespace impactbench::test_support
