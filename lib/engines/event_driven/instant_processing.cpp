#include "lib/engines/event_driven/instant_processing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "lib/engines/event_driven/constraint_projection.hpp"
#include "lib/engines/event_driven/impact_step.hpp"
#include "lib/engines/event_driven/run_record.hpp"
#include "lib/output/message_text.hpp"

namespace impactbench::engines::event_driven {
namespace {

using model::Contact;

// The hint of a candidate whose guard fired.
void set_hint(ModeCandidate& candidate, ContactMode mode, const FiredGuards& fired,
              const FlowAt& before) {
  const auto f = fired.find(candidate.contact->key);
  if (f == fired.end()) return;
  if (f->second == Guard::kLiftoff) {
    candidate.hint = ModeCandidate::Hint::kPreferOpen;
    return;
  }
  if (f->second != Guard::kStickToSlip || mode != ContactMode::kStick) return;
  for (std::size_t j = 0; j < before.closed.size(); ++j) {
    if (before.closed[j].contact->key != candidate.contact->key) continue;
    const Eigen::VectorXd& lambda_t = before.flow.forces[j].lambda_t;
    if (lambda_t.norm() > 0.0) {
      candidate.hint = ModeCandidate::Hint::kForceSlip;
      candidate.forced_slip_direction = -lambda_t.normalized();
    }
  }
}

EventKind mode_change_kind(ContactMode from, ContactMode to) {
  if (to == ContactMode::kOpen) return EventKind::kLiftoff;
  if (from == ContactMode::kOpen) return EventKind::kTouchdown;
  if (to == ContactMode::kStick) return EventKind::kSlipToStick;
  if (from == ContactMode::kStick) return EventKind::kStickToSlip;
  return EventKind::kSlipReversal;
}

}  // namespace

bool same_instant(double earlier, double later) {
  return later - earlier <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(later);
}

std::vector<ModeCandidate> mode_candidates(const std::vector<Contact<double>>& contacts,
                                           const ContactModes& modes, const Eigen::VectorXd& v,
                                           const FiredGuards& fired, const FlowAt& before,
                                           const EventDrivenOptions& options) {
  std::vector<ModeCandidate> candidates;
  for (const auto& c : contacts) {
    const ContactMode mode = modes.mode_of(c.key);
    const double zeta_n = c.relative_velocity(v)[0];
    const bool touching = mode == ContactMode::kOpen && c.gap <= options.gap_tolerance &&
                          std::abs(zeta_n) <= options.velocity_tolerance;
    if (mode == ContactMode::kOpen && !touching) continue;
    ModeCandidate candidate;
    candidate.contact = &c;
    set_hint(candidate, mode, fired, before);
    candidates.push_back(std::move(candidate));
  }
  return candidates;
}

bool InstantProcessor::stalled(double t) {
  if (!same_instant(last_instant_, t)) {
    last_instant_ = t;
    events_at_instant_ = 0;
    return false;
  }
  if (++events_at_instant_ <= run_.options.max_events_per_instant) return false;
  record_failure(result_, SimulationStatus::kStalled,
                 "event-driven: no progress in time at t = " + output::number_text(t) +
                     " s (events keep firing at one instant)");
  return true;
}

bool InstantProcessor::process(double t, Eigen::VectorXd& q, Eigen::VectorXd& v,
                               const FiredGuards& fired, bool initial) {
  if (stalled(t)) return false;
  if (run_.nq != run_.nv) q = run_.normalized_positions(q);  // else q itself
  project_onto_closed_constraints(run_, modes_, q, v);
  // Samples at an event instant: the state entering it (after the drift projection, i.e. what
  // the jump maps act on), then the state leaving it.
  if (!initial && run_.options.sample_events) sampler_.emit(t, q, v);
  const Eigen::VectorXd v_before = v;
  std::vector<Contact<double>>& contacts = contacts_;
  run_.find_contacts(q, v, contacts);
  // Stick forces just before the event: a stick→slip contact slips against them.
  FlowAt before;
  if (std::any_of(fired.begin(), fired.end(),
                  [](const auto& guard) { return guard.second == Guard::kStickToSlip; }))
    evaluate_flow(run_, modes_, t, q, v, before);

  if (!apply_impacts(run_, t, q, v, contacts, initial, modes_, result_)) return false;
  run_.find_contacts(q, v, contacts);  // v may have jumped: drift terms change
  const std::vector<ModeCandidate> candidates =
      mode_candidates(contacts, modes_, v, fired, before, run_.options);
  const DynamicsAtState dynamics = run_.dynamics_at(t, q, v);
  const ModeConsistencyResult consistent =
      make_modes_consistent(dynamics, v, candidates, run_.options);
  result_.summary.enumerated_contact_problems += consistent.enumerated;
  if (!consistent.ok) {
    record_failure(result_, SimulationStatus::kContactSolverFailure, consistent.message);
    return false;
  }
  commit_modes(t, candidates, consistent, initial);
  return record_state(t, q, v, v_before);
}

void InstantProcessor::commit_modes(double t, const std::vector<ModeCandidate>& candidates,
                                    const ModeConsistencyResult& consistent, bool initial) {
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Contact<double>& c = *candidates[i].contact;
    const ModeDecision& decision = consistent.decisions[i];
    TrackedContact& state = modes_.at(c.key);
    const ContactMode from = state.mode;
    const ContactMode to = decision.mode;
    const bool reversed = from == ContactMode::kSlip && to == ContactMode::kSlip &&
                          c.friction > 0.0 && state.slip_reference.size() == c.tangent_dim() &&
                          decision.slip_reference.dot(state.slip_reference) < 0.0;
    state.mode = to;
    if (to == ContactMode::kSlip) state.slip_reference = decision.slip_reference;
    if (to == ContactMode::kOpen) state.impacts_in_row = 0;
    if (initial || (from == to && !reversed)) continue;
    record_event(result_, make_event(t, c, mode_change_kind(from, to), from, to));
  }
}

bool InstantProcessor::record_state(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                    const Eigen::VectorXd& v_before) {
  EventState snapshot;
  snapshot.t = t;
  snapshot.q = q;
  snapshot.v = v;
  snapshot.v_before = v_before;
  snapshot.modes = modes_.closed_modes();
  result_.event_states.push_back(std::move(snapshot));
  if (static_cast<int>(result_.events.size()) < run_.options.max_events) return true;
  record_failure(result_, SimulationStatus::kMaxEvents,
                 "event-driven: reached max_events = " + std::to_string(run_.options.max_events) +
                     " at t = " + output::number_text(t) + " s");
  return false;
}

}  // namespace impactbench::engines::event_driven
