#pragma once
// The Zeno rule of the event-driven integrator: when an impact would be followed by more
// impacts after vanishing flights, the contact rests instead (persistent, ζ_n = 0) and the time
// at which those impacts would have accumulated is predicted. A pure function of one contact's
// impact, so that it is tested on its own.
#include "lib/engines/event_driven/event_driven_options.hpp"

namespace impactbench::engines::event_driven {

/// One contact that bounces off at an impact (ζ_n⁺ above the resting velocity).
struct ZenoCandidate {
  double t = 0.0;                    ///< time of the impact [s]
  double predicted_interval = 0.0;   ///< time to its next impact, 2ζ_n⁺/|a_n| (∞: none) [s]
  int impacts_before = 0;            ///< consecutive impacts of the contact before this one
  double normal_velocity_after = 0;  ///< ζ_n⁺ [m/s]
  double restitution = 0.0;          ///< e of this impact [-]
};

struct ZenoDecision {
  bool rest = false;  ///< the contact rests: the impact is recomputed with e = 0 for it
  /// When resting: t + Δt/(1 − e), the sum of the geometric series of the remaining flights
  /// (t itself when e ≥ 1 or no next impact is predicted) [s].
  double accumulation_time = 0.0;
};

/// Rest when the next flight would be shorter than options.zeno_min_interval, or when this is
/// at least the options.zeno_impact_count-th impact in a row and ζ_n⁺ < options.zeno_velocity.
ZenoDecision decide_zeno(const ZenoCandidate& candidate, const EventDrivenOptions& options);

}  // namespace impactbench::engines::event_driven
