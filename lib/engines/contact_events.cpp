#include "lib/engines/contact_events.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impactbench::engines {

ContactEvents::ContactEvents(ImpactCriteria criteria) : criteria_(criteria) {
  if (!(criteria_.impact_velocity >= 0.0) || !std::isfinite(criteria_.impact_velocity) ||
      !(criteria_.impact_open_time >= 0.0) || !std::isfinite(criteria_.impact_open_time))
    throw std::invalid_argument("impact_velocity and impact_open_time must be finite and >= 0");
}

void ContactEvents::after_step(double t, const std::vector<ClosedContact>& closed,
                               std::vector<output::EventRecord>& events) {
  ++call_;
  closed_now_.clear();
  for (const ClosedContact& c : closed) {
    auto& entry = *histories_.try_emplace(c.name).first;
    History& history = entry.second;
    if (history.closed_after != call_) {  // its first mention in this list
      history.was_closed = history.closed_after == call_ - 1;
      history.closed_after = call_;
      closed_now_.push_back(&entry);
    }
    if (history.was_closed) continue;
    const double open_for = t - (history.lifted ? history.opened_at : 0.0);
    const bool impact =
        c.approach_speed > criteria_.impact_velocity || open_for > criteria_.impact_open_time;
    events.push_back(
        {t, c.name, impact ? "impact" : "closure", "open", "closed", c.impulse_n, c.impulse_t});
  }
  // Lift-offs in the order of their names, as an ordered set of the closed contacts gave them.
  lifted_.clear();
  for (Histories::value_type* entry : closed_)
    if (entry->second.closed_after != call_) lifted_.push_back(entry);
  std::sort(lifted_.begin(), lifted_.end(),
            [](const auto* a, const auto* b) { return a->first < b->first; });
  for (Histories::value_type* entry : lifted_) {
    events.push_back({t, entry->first, "liftoff", "closed", "open", 0.0, 0.0});
    entry->second.lifted = true;
    entry->second.opened_at = t;
  }
  closed_.swap(closed_now_);
}

}  // namespace impactbench::engines
