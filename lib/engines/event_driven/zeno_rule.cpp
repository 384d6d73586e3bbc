#include "lib/engines/event_driven/zeno_rule.hpp"

#include <cmath>

namespace impactbench::engines::event_driven {

ZenoDecision decide_zeno(const ZenoCandidate& candidate, const EventDrivenOptions& options) {
  const double interval = candidate.predicted_interval;
  const int count = candidate.impacts_before + 1;
  ZenoDecision decision;
  decision.rest = interval < options.zeno_min_interval ||
                  (count >= options.zeno_impact_count &&
                   candidate.normal_velocity_after < options.zeno_velocity);
  if (!decision.rest) return decision;
  const double e = candidate.restitution;
  decision.accumulation_time =
      e < 1.0 && std::isfinite(interval) ? candidate.t + interval / (1.0 - e) : candidate.t;
  return decision;
}

}  // namespace impactbench::engines::event_driven
