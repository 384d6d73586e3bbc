#include "lib/engines/event_driven/impact_step.hpp"

#include <algorithm>
#include <limits>

#include "lib/engines/event_driven/run_record.hpp"

namespace impactbench::engines::event_driven {
namespace {

using model::Contact;
using model::ContactKey;

// predicted_impact_interval's contacts, flow and frame, kept per thread: it runs at every impact.
struct PredictionScratch {
  std::vector<Contact<double>> contacts;
  std::vector<ClosedContact> closed;
  FlowWorkspace work;
  FlowSolution flow;
  ContactFrame frame;
};

// Ballistic estimate 2ζ_n/|a_n| of the next flight of contact `key`, with the contacts that
// stay closed held fixed (stick): only the size of the normal acceleration matters here.
double predicted_impact_interval(const RunContext& run, double t, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& v, const ContactKey& key,
                                 const std::vector<ContactKey>& closing) {
  thread_local PredictionScratch w;
  run.find_contacts(q, v, w.contacts);
  const Contact<double>* c = find_contact(w.contacts, key);
  if (c == nullptr) return std::numeric_limits<double>::infinity();
  w.closed.clear();
  for (const auto& other : w.contacts)
    for (const auto& k : closing)
      if (other.key == k) w.closed.push_back({&other, ContactMode::kStick, Eigen::VectorXd()});
  const DynamicsAtState dynamics = run.dynamics_at(t, q, v);
  solve_constrained_flow(dynamics, v, w.closed, run.options, w.work, w.flow);
  w.frame.assign(*c, run.nv);
  const double zeta_n = w.frame.J.col(0).dot(v);
  const double accel_n = w.frame.J.col(0).dot(w.flow.vdot) + w.frame.drift[0];
  if (!(accel_n < 0.0)) return std::numeric_limits<double>::infinity();
  return 2.0 * zeta_n / -accel_n;
}

// The event of participant i's impact (or of its lift-off by the impulse of others).
Event impact_event(double t, const Contact<double>& c, const ContactImpulse& ci, bool impacting,
                   const ZenoDecision& zeno, ContactMode from, ContactMode to) {
  EventKind kind = EventKind::kLiftoff;
  if (impacting) kind = zeno.rest ? EventKind::kZenoRest : EventKind::kImpact;
  Event e = make_event(t, c, kind, from, to);
  e.impulse_n = ci.impulse[0];
  e.impulse_t = ci.impulse.tail(c.tangent_dim());
  e.normal_velocity_before = ci.zeta_before[0];
  e.normal_velocity_after = ci.zeta_after[0];
  e.impact_map = impacting ? ci.map : ContactMode::kOpen;
  e.gamma = ci.gamma;
  e.accumulation_time = zeno.accumulation_time;
  return e;
}

// The mode after the impulse: closed (by its map) when it ends at rest, else open.
ContactMode mode_after_impact(const ContactImpulse& ci, int d, double velocity_tolerance,
                              TrackedContact& state) {
  if (!(ci.zeta_after[0] <= velocity_tolerance)) return ContactMode::kOpen;
  if (ci.map == ContactMode::kSlip) {
    const Eigen::VectorXd zeta_t = ci.zeta_after.tail(d);
    state.slip_reference =
        zeta_t.norm() > 0.0 ? Eigen::VectorXd(zeta_t.normalized()) : Eigen::VectorXd::Unit(d, 0);
  }
  return ci.map;
}

void commit_impacts(double t, const ImpactParticipants& participants, const ImpactResult& impact,
                    const std::vector<ZenoDecision>& zeno, bool initial,
                    const EventDrivenOptions& options, ContactModes& modes,
                    EventDrivenResult& result) {
  for (std::size_t i = 0; i < participants.contacts.size(); ++i) {
    if (participants.touching[i]) continue;
    const Contact<double>& c = *participants.contacts[i];
    const ContactImpulse& ci = impact.contacts[i];
    const bool impacting = participants.impacting[i];
    TrackedContact& state = modes.at(c.key);
    const ContactMode from = state.mode;
    const ContactMode to =
        mode_after_impact(ci, c.tangent_dim(), options.velocity_tolerance, state);
    state.mode = to;
    if (!impacting && to != ContactMode::kOpen) continue;  // stays closed: modes settle later
    if (impacting)
      state.impacts_in_row = zeno[i].rest ? 0 : state.impacts_in_row + 1;
    else
      state.impacts_in_row = 0;
    if (initial && !impacting) continue;
    record_event(result, impact_event(t, c, ci, impacting, zeno[i], from, to));
  }
}

}  // namespace

bool ImpactParticipants::any_impacting() const {
  return std::find(impacting.begin(), impacting.end(), true) != impacting.end();
}

ImpactParticipants impact_participants(const std::vector<Contact<double>>& contacts,
                                       const ContactModes& modes, const Eigen::VectorXd& v,
                                       const EventDrivenOptions& options) {
  ImpactParticipants out;
  for (const auto& c : contacts) {
    const ContactMode mode = modes.mode_of(c.key);
    const bool open_at_surface = mode == ContactMode::kOpen && c.gap <= options.gap_tolerance;
    const bool closing = open_at_surface && c.relative_velocity(v)[0] < -options.velocity_tolerance;
    if (open_at_surface || mode != ContactMode::kOpen) {
      out.contacts.push_back(&c);
      out.impacting.push_back(closing);
      out.touching.push_back(open_at_surface && !closing);
      out.restitution.push_back(c.restitution);
    }
  }
  return out;
}

ImpactResult solve_impact(const DynamicsAtState& dynamics, const Eigen::VectorXd& v,
                          const ImpactParticipants& participants,
                          const EventDrivenOptions& options) {
  if (participants.contacts.size() == 1)
    return single_contact_impact(dynamics, v, *participants.contacts[0],
                                 participants.restitution[0], options);
  return simultaneous_impact(dynamics, v, participants.contacts, participants.restitution, options);
}

std::vector<ZenoDecision> zeno_decisions(const RunContext& run, const ContactModes& modes, double t,
                                         const Eigen::VectorXd& q, const ImpactResult& impact,
                                         ImpactParticipants& participants) {
  const double resting = run.options.velocity_tolerance;
  const std::size_t n = participants.contacts.size();
  std::vector<ContactKey> closing_keys;
  for (std::size_t i = 0; i < n; ++i)
    if (impact.contacts[i].zeta_after[0] <= resting)
      closing_keys.push_back(participants.contacts[i]->key);
  std::vector<ZenoDecision> decisions(n);
  for (std::size_t i = 0; i < n; ++i) {
    ZenoCandidate candidate;
    candidate.normal_velocity_after = impact.contacts[i].zeta_after[0];
    if (!participants.impacting[i] || candidate.normal_velocity_after <= resting) continue;
    const ContactKey& key = participants.contacts[i]->key;
    candidate.t = t;
    candidate.predicted_interval =
        predicted_impact_interval(run, t, q, impact.v_plus, key, closing_keys);
    candidate.impacts_before = modes.impacts_in_row(key);
    candidate.restitution = participants.restitution[i];
    decisions[i] = decide_zeno(candidate, run.options);
    if (decisions[i].rest) participants.restitution[i] = 0.0;
  }
  return decisions;
}

bool apply_impacts(const RunContext& run, double t, const Eigen::VectorXd& q, Eigen::VectorXd& v,
                   const std::vector<Contact<double>>& contacts, bool initial, ContactModes& modes,
                   EventDrivenResult& result) {
  ImpactParticipants participants = impact_participants(contacts, modes, v, run.options);
  if (!participants.any_impacting()) return true;
  const DynamicsAtState dynamics = run.dynamics_at(t, q, v);
  // Each solve counted in the summary when its problem needed enumeration.
  const auto solve = [&] {
    ImpactResult solved = solve_impact(dynamics, v, participants, run.options);
    if (solved.enumerated) ++result.summary.enumerated_contact_problems;
    return solved;
  };
  ImpactResult impact = solve();
  if (impact.ok) {
    // Zeno: contacts that would bounce again after a vanishing interval rest instead.
    const std::vector<ZenoDecision> zeno = zeno_decisions(run, modes, t, q, impact, participants);
    if (std::any_of(zeno.begin(), zeno.end(), [](const ZenoDecision& z) { return z.rest; }))
      impact = solve();
    if (impact.ok) {
      v = impact.v_plus;
      commit_impacts(t, participants, impact, zeno, initial, run.options, modes, result);
      return true;
    }
  }
  record_failure(result, SimulationStatus::kContactSolverFailure, impact.message);
  return false;
}

}  // namespace impactbench::engines::event_driven
