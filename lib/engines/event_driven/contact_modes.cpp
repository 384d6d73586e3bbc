#include "lib/engines/event_driven/contact_modes.hpp"

#include <algorithm>

namespace impactbench::engines::event_driven {

ContactMode ContactModes::mode_of(const model::ContactKey& key) const {
  const auto it = tracked_.find(key);
  return it == tracked_.end() ? ContactMode::kOpen : it->second.mode;
}

int ContactModes::impacts_in_row(const model::ContactKey& key) const {
  const auto it = tracked_.find(key);
  return it == tracked_.end() ? 0 : it->second.impacts_in_row;
}

bool ContactModes::all_open() const {
  return std::none_of(tracked_.begin(), tracked_.end(),
                      [](const auto& entry) { return entry.second.mode != ContactMode::kOpen; });
}

std::vector<ClosedContact> ContactModes::closed_among(
    const std::vector<model::Contact<double>>& contacts) const {
  std::vector<ClosedContact> closed;
  closed_among(contacts, closed);
  return closed;
}

void ContactModes::closed_among(const std::vector<model::Contact<double>>& contacts,
                                std::vector<ClosedContact>& closed) const {
  std::size_t n = 0;
  for (const auto& c : contacts) {
    const auto it = tracked_.find(c.key);
    if (it == tracked_.end() || it->second.mode == ContactMode::kOpen) continue;
    if (n == closed.size()) closed.emplace_back();
    // Assigned field by field, so that its slip_reference keeps its storage.
    ClosedContact& entry = closed[n++];
    entry.contact = &c;
    entry.mode = it->second.mode;
    entry.slip_reference = it->second.slip_reference;
  }
  closed.resize(n);
}

std::map<model::ContactKey, ContactMode> ContactModes::closed_modes() const {
  std::map<model::ContactKey, ContactMode> modes;
  for (const auto& [key, state] : tracked_)
    if (state.mode != ContactMode::kOpen) modes[key] = state.mode;
  return modes;
}

}  // namespace impactbench::engines::event_driven
