#pragma once
// Vocabulary of the event-driven hybrid integrator (source B.3): the mode of each contact, the
// kinds of events, one logged event, output samples, the run's status and its result.
#include <array>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/sample_table.hpp"
#include "lib/model/contact.hpp"

namespace impactbench::engines::event_driven {

/// Mode of one contact (B.3.3): open (0), slip (1), stick (2).
enum class ContactMode { kOpen, kSlip, kStick };

/// What happened at an event.
enum class EventKind {
  kImpact,        ///< A closing gap reached zero with ζ_n < 0: jump map B.19–B.24.
  kTouchdown,     ///< A gap reached zero with ζ_n = 0 (grazing): closed without impulse.
  kLiftoff,       ///< λ_n reached zero on a closed contact (B.38/B.42), or the contact opened.
  kSlipToStick,   ///< ‖ζ_t‖ reached zero and the cone holds the required force (B.39).
  kStickToSlip,   ///< ‖λ_t‖ reached μλ_n (B.43 with μ).
  kSlipReversal,  ///< ‖ζ_t‖ reached zero and the contact slips on in another direction.
  kZenoRest,      ///< Accumulating impacts ended by making the contact persistent.
};
inline constexpr int kNumEventKinds = 7;

std::string_view to_string(ContactMode mode);
std::string_view to_string(EventKind kind);

/// Why the run stopped. Failures are values, not exceptions (invalid arguments still throw).
enum class SimulationStatus {
  kSuccess,               ///< Reached the requested duration.
  kMaxEvents,             ///< Stopped after `max_events` events.
  kIntegratorFailure,     ///< CVODE failed (error test / convergence failures, step too small).
  kContactSolverFailure,  ///< An impulse- or acceleration-level complementarity solve failed.
  kSingularDynamics,      ///< The constrained dynamics had no solution (inconsistent modes).
  kStalled,               ///< Too many events at one instant (no progress in time).
};
std::string_view to_string(SimulationStatus status);

/// One logged event; one entry per contact whose mode or velocity jumps.
struct Event {
  double t = 0.0;       ///< [s]
  std::string contact;  ///< Contact name (model::Contact::name).
  model::ContactKey key;
  EventKind kind = EventKind::kImpact;
  ContactMode from_mode = ContactMode::kOpen;
  ContactMode to_mode = ContactMode::kOpen;
  double impulse_n = 0.0;               ///< Λ_n [N s]
  Eigen::VectorXd impulse_t;            ///< Λ_t [N s], size d (0 when no impulse)
  double normal_velocity_before = 0.0;  ///< ζ_n⁻ [m/s]
  double normal_velocity_after = 0.0;   ///< ζ_n⁺ [m/s]
  /// Impacts only: the map used, stick (B.22–B.24) or slip (B.19–B.21), and Γ of B.25 for
  /// single-contact impacts (NaN for simultaneous ones).
  ContactMode impact_map = ContactMode::kOpen;
  double gamma = 0.0;
  /// Zeno rest only: the accumulation time predicted from the geometric series of the
  /// remaining bounces t_k + Δt_next / (1 − e) [s].
  double accumulation_time = 0.0;

  /// Scalar tangential impulse for the CSV: the signed value in the plane, the norm in space.
  double impulse_t_scalar() const;
};

/// The accumulation point t∞ of a contact's impacts, as predicted at its Zeno rest.
struct ZenoLimit {
  double t = 0.0;  ///< [s]
  std::string contact;
  ContactMode mode = ContactMode::kStick;  ///< the mode the contact rests in from the cut-off
};

/// One per zeno_rest event, in event order.
std::vector<ZenoLimit> zeno_limits(const std::vector<Event>& events);

/// State after an event instant (all events of one instant share it).
struct EventState {
  double t = 0.0;
  Eigen::VectorXd q, v;
  Eigen::VectorXd v_before;  ///< velocity just before the instant (differs from v at impacts)
  std::map<model::ContactKey, ContactMode> modes;  ///< Closed contacts only.
};

struct EventSummary {
  std::array<int, kNumEventKinds> counts{};  ///< indexed by EventKind
  int total() const;
  int count(EventKind kind) const { return counts[static_cast<int>(kind)]; }
  long rhs_evaluations = 0;
  long root_evaluations = 0;  ///< evaluations of the guard (root) functions by CVODE
  long steps = 0;
  long segments = 0;  ///< CVODE (re)initialisations
  /// Most contacts tracked with root functions in one segment (those within contact_margin).
  long max_tracked_contacts = 0;
  /// Planar contact problems (impulse or acceleration level) that the LCP solver failed and
  /// enumeration solved (local_contact_problem.hpp).
  long enumerated_contact_problems = 0;
  double engine_cpu_seconds = 0.0;  ///< process CPU time of the integration [s]
  double record_cpu_seconds = 0.0;  ///< process CPU time of emitting the samples [s]
  double wall_seconds = 0.0;        ///< wall-clock time of the run [s]
  /// One line per kind, e.g. "impact: 12".
  std::string to_text() const;
};

struct EventDrivenResult {
  SimulationStatus status = SimulationStatus::kSuccess;
  std::string message;  ///< Why the run stopped early (empty on success).
  double final_time = 0.0;
  Eigen::VectorXd q, v;  ///< Final state.
  SampleTable samples;   ///< Empty when the run had an observer.
  std::vector<Event> events;
  std::vector<EventState> event_states;  ///< Post-event states, one per event instant.
  EventSummary summary;
  bool succeeded() const { return status == SimulationStatus::kSuccess; }
};

}  // namespace impactbench::engines::event_driven
