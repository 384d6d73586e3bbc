#include "lib/sensitivity/hybrid_mode.hpp"

#include <stdexcept>

namespace impactbench::sensitivity {

bool is_closed(ContactPhase phase) {
  return phase != ContactPhase::kOpen;
}

int slip_direction(ContactPhase phase) {
  switch (phase) {
    case ContactPhase::kSlipPositive:
      return 1;
    case ContactPhase::kSlipNegative:
      return -1;
    default:
      return 0;
  }
}

const std::vector<double>& HybridMode::reference(int i) const {
  static const std::vector<double> none;
  const auto k = static_cast<std::size_t>(i);
  return k < slip_reference.size() ? slip_reference[k] : none;
}

HybridMode apply_event(const HybridMode& mode, const MicroEvent& event) {
  if (event.contact < 0 || event.contact >= static_cast<int>(mode.size()))
    throw std::invalid_argument("sensitivity: micro event names contact " +
                                std::to_string(event.contact) + " of a mode with " +
                                std::to_string(mode.size()) + " contacts");
  HybridMode next = mode;
  next[static_cast<std::size_t>(event.contact)] = event.phase_after;
  if (!event.slip_reference.empty() || !next.slip_reference.empty()) {
    next.slip_reference.resize(mode.size());
    next.slip_reference[static_cast<std::size_t>(event.contact)] = event.slip_reference;
  }
  for (const CarriedPhase& c : event.carried) {
    const bool valid = event.kind == GuardKind::kImpact && c.contact != event.contact &&
                       c.contact >= 0 && c.contact < static_cast<int>(mode.size()) &&
                       is_closed(mode[static_cast<std::size_t>(c.contact)]);
    if (!valid)
      throw std::invalid_argument(
          "sensitivity: micro event " + to_string(event) + " carries a phase change of contact " +
          std::to_string(c.contact) + " (only an impact may, of another closed contact)");
    next[static_cast<std::size_t>(c.contact)] = c.phase_after;
    if (!next.slip_reference.empty()) next.slip_reference[static_cast<std::size_t>(c.contact)] = {};
  }
  return next;
}

std::string_view to_string(ContactPhase phase) {
  switch (phase) {
    case ContactPhase::kOpen:
      return "open";
    case ContactPhase::kSlipPositive:
      return "slip+";
    case ContactPhase::kSlipNegative:
      return "slip-";
    case ContactPhase::kStick:
      return "stick";
  }
  return "?";
}

std::string_view to_string(GuardKind kind) {
  switch (kind) {
    case GuardKind::kImpact:
      return "impact";
    case GuardKind::kLiftOff:
      return "lift_off";
    case GuardKind::kSlipToStick:
      return "slip_to_stick";
    case GuardKind::kStickToSlip:
      return "stick_to_slip";
  }
  return "?";
}

std::string to_string(const MicroEvent& event) {
  std::string text = std::to_string(event.contact) + ":" + std::string(to_string(event.kind)) +
                     "->" + std::string(to_string(event.phase_after));
  for (const CarriedPhase& c : event.carried)
    text += " (" + std::to_string(c.contact) + "->" + std::string(to_string(c.phase_after)) + ")";
  return text;
}

std::string to_string(const HybridMode& mode) {
  std::string text;
  for (std::size_t i = 0; i < mode.size(); ++i) {
    if (i > 0) text += '|';
    text += to_string(mode[i]);
  }
  return text;
}

}  // namespace impactbench::sensitivity
