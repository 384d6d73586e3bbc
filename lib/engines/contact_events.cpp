#include "lib/engines/contact_events.hpp"

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
  std::set<std::string> closed_now;
  for (const ClosedContact& c : closed) {
    closed_now.insert(c.name);
    if (closed_.count(c.name)) continue;
    const auto opened = opened_at_.find(c.name);
    const double open_for = t - (opened == opened_at_.end() ? 0.0 : opened->second);
    const bool impact =
        c.approach_speed > criteria_.impact_velocity || open_for > criteria_.impact_open_time;
    events.push_back(
        {t, c.name, impact ? "impact" : "closure", "open", "closed", c.impulse_n, c.impulse_t});
  }
  for (const std::string& name : closed_)
    if (!closed_now.count(name)) {
      events.push_back({t, name, "liftoff", "closed", "open", 0.0, 0.0});
      opened_at_[name] = t;
    }
  closed_ = std::move(closed_now);
}

}  // namespace impactbench::engines
