#pragma once
// Output of the event-driven integrator in the design's formats: the events CSV
// (`t,contact,kind,from_mode,to_mode,impulse_n,impulse_t`) and the summary of counts by kind.
#include <ostream>
#include <vector>

#include "lib/engines/event_driven/event_types.hpp"

namespace impactbench::engines::event_driven {

/// Header plus one row per event; times and impulses with 17 significant digits.
void write_events_csv(std::ostream& out, const std::vector<Event>& events);

/// "status: …", the counts by kind, the total, and the CVODE work counters.
void write_summary(std::ostream& out, const EventDrivenResult& result);

}  // namespace impactbench::engines::event_driven
