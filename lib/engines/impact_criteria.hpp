#pragma once
// When a time-stepper's closing contact counts as an impact (lib/engines/contact_events.hpp):
// two settings of every time-stepping engine (lib/engines/impact_criteria_fields.hpp).

namespace impactbench::engines {

/// Engine settings `impact_velocity` and `impact_open_time`.
struct ImpactCriteria {
  /// [m/s] Approach speeds above it are impacts. A contact that opens for n steps under gravity
  /// re-closes at about n g h (a rocking block's corner at h = 0.1 ms: below 0.009 m/s); the
  /// shipped scenarios' impacts approach at 0.04 m/s and faster.
  double impact_velocity = 0.02;
  /// [s] A contact open for longer than this impacts whatever its speed, so a slow landing after
  /// a flight is an impact. A ballistic bounce at approach speed v flies about 2 v / g: 2 ms
  /// resolves bounces down to 0.01 m/s (the event-driven engine's zeno_velocity), and a
  /// contact that opens for one or two steps of 1 ms is not an impact.
  double impact_open_time = 2e-3;
};

}  // namespace impactbench::engines
