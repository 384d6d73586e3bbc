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
  for (const auto& c : contacts) {
    const auto it = tracked_.find(c.key);
    if (it == tracked_.end() || it->second.mode == ContactMode::kOpen) continue;
    closed.push_back({&c, it->second.mode, it->second.slip_reference});
  }
  return closed;
}

std::map<model::ContactKey, ContactMode> ContactModes::closed_modes() const {
  std::map<model::ContactKey, ContactMode> modes;
  for (const auto& [key, state] : tracked_)
    if (state.mode != ContactMode::kOpen) modes[key] = state.mode;
  return modes;
}

}  // namespace impactbench::engines::event_driven
