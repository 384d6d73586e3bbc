#pragma once
// What a run writes into its result while it goes: the events (and their counts) and the first
// failure.
#include <string>

#include "lib/engines/event_driven/event_types.hpp"

namespace impactbench::engines::event_driven {

/// An event at contact `c` with no impulse (filled in by impacts).
Event make_event(double t, const model::Contact<double>& c, EventKind kind, ContactMode from,
                 ContactMode to);
/// Appends the event and counts it by kind.
void record_event(EventDrivenResult& result, Event event);
/// Sets the status and message, unless an earlier failure was recorded.
void record_failure(EventDrivenResult& result, SimulationStatus status, std::string message);

}  // namespace impactbench::engines::event_driven
