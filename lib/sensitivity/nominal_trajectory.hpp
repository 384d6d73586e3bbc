#pragma once
// The nominal hybrid trajectory α(t) with input μ(t) that the sensitivity module linearises
// about, in the smallest form that determines it: the initial state and mode, and the macro
// events (time and the micro events crossed then). The states between events are integrated by
// the module itself (with the model's mode vector fields), which is also where A(t), B(t) are
// needed; an event-driven run supplies the post-event states it found, which restart each
// segment so that integration errors do not accumulate across events.
#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "lib/sensitivity/hybrid_mode.hpp"

namespace impactbench::sensitivity {

/// A function of time with values in input space (μ(t), μ̇(t), or an input perturbation v(t)).
using InputFunction = std::function<Eigen::VectorXd(double t)>;

struct NominalEvent {
  double time = 0.0;                     ///< τ [s]
  std::vector<MicroEvent> micro_events;  ///< in the nominal order (any order if simultaneous)
  /// The post-event state reported by the simulator; empty: computed by the reset maps.
  std::optional<Eigen::VectorXd> x_plus;
};

struct NominalTrajectory {
  double t_begin = 0.0;
  double t_end = 0.0;
  Eigen::VectorXd x0;  ///< (q, v) at t_begin
  HybridMode mode0;
  std::vector<NominalEvent> events;  ///< strictly increasing times in (t_begin, t_end)
  InputFunction input;               ///< μ(t); empty: no input
  InputFunction input_rate;          ///< μ̇(t); empty: zero

  /// Throws std::invalid_argument naming what is wrong (times out of order, empty events,
  /// non-finite x0).
  void validate(int state_size, int num_contacts) const;
  Eigen::VectorXd input_at(double t, int input_size) const;
  Eigen::VectorXd input_rate_at(double t, int input_size) const;
};

}  // namespace impactbench::sensitivity
