#include "lib/engines/event_driven/event_types.hpp"

#include <sstream>

namespace impactbench::engines::event_driven {

std::string_view to_string(ContactMode mode) {
  switch (mode) {
    case ContactMode::kOpen:
      return "open";
    case ContactMode::kSlip:
      return "slip";
    case ContactMode::kStick:
      return "stick";
  }
  return "?";
}

std::string_view to_string(EventKind kind) {
  switch (kind) {
    case EventKind::kImpact:
      return "impact";
    case EventKind::kTouchdown:
      return "touchdown";
    case EventKind::kLiftoff:
      return "liftoff";
    case EventKind::kSlipToStick:
      return "slip_to_stick";
    case EventKind::kStickToSlip:
      return "stick_to_slip";
    case EventKind::kSlipReversal:
      return "slip_reversal";
    case EventKind::kZenoRest:
      return "zeno_rest";
  }
  return "?";
}

std::string_view to_string(SimulationStatus status) {
  switch (status) {
    case SimulationStatus::kSuccess:
      return "success";
    case SimulationStatus::kMaxEvents:
      return "max_events";
    case SimulationStatus::kIntegratorFailure:
      return "integrator_failure";
    case SimulationStatus::kContactSolverFailure:
      return "contact_solver_failure";
    case SimulationStatus::kSingularDynamics:
      return "singular_dynamics";
    case SimulationStatus::kStalled:
      return "stalled";
  }
  return "?";
}

double Event::impulse_t_scalar() const {
  if (impulse_t.size() == 1) return impulse_t[0];
  return impulse_t.size() == 0 ? 0.0 : impulse_t.norm();
}

int EventSummary::total() const {
  int sum = 0;
  for (int c : counts) sum += c;
  return sum;
}

std::string EventSummary::to_text() const {
  std::ostringstream out;
  for (int k = 0; k < kNumEventKinds; ++k)
    out << to_string(static_cast<EventKind>(k)) << ": " << counts[k] << '\n';
  out << "total: " << total() << '\n';
  return out.str();
}

std::vector<ZenoLimit> zeno_limits(const std::vector<Event>& events) {
  std::vector<ZenoLimit> limits;
  for (const Event& e : events)
    if (e.kind == EventKind::kZenoRest)
      limits.push_back({e.accumulation_time, e.contact, e.to_mode});
  return limits;
}

}  // namespace impactbench::engines::event_driven
