#include "lib/engines/event_driven/run_record.hpp"

#include <utility>

namespace impactbench::engines::event_driven {

Event make_event(double t, const model::Contact<double>& c, EventKind kind, ContactMode from,
                 ContactMode to) {
  Event e;
  e.t = t;
  e.contact = c.name;
  e.key = c.key;
  e.kind = kind;
  e.from_mode = from;
  e.to_mode = to;
  e.impulse_t = Eigen::VectorXd::Zero(c.tangent_dim());
  return e;
}

void record_event(EventDrivenResult& result, Event event) {
  ++result.summary.counts[static_cast<int>(event.kind)];
  result.events.push_back(std::move(event));
}

void record_failure(EventDrivenResult& result, SimulationStatus status, std::string message) {
  if (result.status != SimulationStatus::kSuccess) return;
  result.status = status;
  result.message = std::move(message);
}

}  // namespace impactbench::engines::event_driven
