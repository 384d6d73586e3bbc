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
#include <string>
#include <unordered_map>
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
  // A contact ever closed, by name (a pile's step closes thousands: looked up by hash, not in
  // an ordered set).
  struct History {
    long closed_after = -2;   // the last call (0, 1, ...) after whose step it was closed
    bool was_closed = false;  // closed after the step before that call's
    bool lifted = false;      // it lifted off at `opened_at`
    double opened_at = 0.0;
  };
  using Histories = std::unordered_map<std::string, History>;

  ImpactCriteria criteria_;
  long call_ = -1;                                  // calls so far − 1
  Histories histories_;                             // element pointers stay valid as the map grows
  std::vector<Histories::value_type*> closed_;      // closed after the previous step, each once
  std::vector<Histories::value_type*> closed_now_;  // kept storage for the next list
  std::vector<Histories::value_type*> lifted_;      // kept storage: this step's lift-offs
};

}  // namespace impactbench::engines
