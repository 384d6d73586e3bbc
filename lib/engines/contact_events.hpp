#pragma once
// The events of a time-stepping engine (Moreau–Jean, Box2D, Bullet), derived in one place from
// the set of contacts closed after each step. A time-stepper lets a loaded contact open for a
// step now and then (a rocking block's pivot corner lifts by round-off and settles back), so a
// contact that closes is an impact only when it is one:
//
//   impact   it approaches faster than `impact_velocity` (the relative normal velocity at the
//            start of the step), or it was open for longer than `impact_open_time`;
//   closure  any other contact that closes: it re-closes after a short opening, or was placed
//            touching;
//   liftoff  a closed contact that is no longer closed.
//
// A contact that has never been closed counts as open since the start of the run.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "lib/engines/impact_criteria.hpp"
#include "lib/output/trajectory.hpp"

namespace impactbench::engines {

/// One contact closed at the end of a step.
struct ClosedContact {
  std::string name;
  double approach_speed = 0.0;  ///< −ζ_n at the start of the step [m/s], > 0 when closing
  double impulse_n = 0.0;       ///< normal impulse of the step [N·s]
  double impulse_t = 0.0;       ///< tangential impulse (signed planar, magnitude spatial) [N·s]
};

class ContactEvents {
 public:
  /// Throws std::invalid_argument unless both criteria are finite and >= 0.
  explicit ContactEvents(ImpactCriteria criteria);

  /// The contacts closed after the step ending at `t` (each name once); appends to `events`
  /// one impact or closure per contact that was open, and one lift-off per contact that was
  /// closed and is no longer.
  void after_step(double t, const std::vector<ClosedContact>& closed,
                  std::vector<output::EventRecord>& events);

 private:
  ImpactCriteria criteria_;
  std::set<std::string> closed_;             // closed after the previous step
  std::map<std::string, double> opened_at_;  // contacts that lifted off: when
};

}  // namespace impactbench::engines
