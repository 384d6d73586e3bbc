#pragma once
// One event instant: the guards that fired at time t, processed in order — drift projection,
// impacts (impact_step.hpp), then the acceleration-level mode decision over every closed and
// touching contact (mode_consistency.hpp) — with the events it logs, the state after it, and
// the limits on events (max_events, max_events_per_instant).
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/contact_modes.hpp"
#include "lib/engines/event_driven/guard_set.hpp"
#include "lib/engines/event_driven/mode_consistency.hpp"
#include "lib/engines/event_driven/run_context.hpp"
#include "lib/engines/event_driven/sampler.hpp"

namespace impactbench::engines::event_driven {

/// True when two event times are one instant: equal to within a few units of round-off. CVODE
/// never returns two times that close: a root comes at least half its root tolerance,
/// 50 ε (|t| + |h|), after the segment's start, a step end at least one step (≥ 10⁻⁸ s
/// by default), so on a run that progresses this is exact equality; it also catches events
/// that keep firing at times one round-off apart.
bool same_instant(double earlier, double later);

/// The mode candidates of an instant: every closed contact and every open one touching with
/// no normal velocity, with the hints of the guards that fired (lift-off: prefer open;
/// stick→slip: slip against the stick force `before` held).
std::vector<ModeCandidate> mode_candidates(const std::vector<model::Contact<double>>& contacts,
                                           const ContactModes& modes, const Eigen::VectorXd& v,
                                           const FiredGuards& fired, const FlowAt& before,
                                           const EventDrivenOptions& options);

class InstantProcessor {
 public:
  InstantProcessor(const RunContext& run, ContactModes& modes, Sampler& sampler,
                   EventDrivenResult& result)
      : run_(run), modes_(modes), sampler_(sampler), result_(result) {}

  /// Processes the instant t with the state (q, v) entering it, which becomes the state leaving
  /// it. `initial`: the start of the run (modes settle without events). False, with the failure
  /// recorded, when the run must stop.
  bool process(double t, Eigen::VectorXd& q, Eigen::VectorXd& v, const FiredGuards& fired,
               bool initial);

 private:
  bool stalled(double t);
  void commit_modes(double t, const std::vector<ModeCandidate>& candidates,
                    const ModeConsistencyResult& consistent, bool initial);
  bool record_state(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                    const Eigen::VectorXd& v_before);

  const RunContext& run_;
  ContactModes& modes_;
  Sampler& sampler_;
  EventDrivenResult& result_;
  double last_instant_ = -1.0;
  int events_at_instant_ = 0;
  std::vector<model::Contact<double>> contacts_;  // at the instant (storage kept)
};

}  // namespace impactbench::engines::event_driven
