#include "lib/sensitivity/event_driven_nominal.hpp"
#include "lib/output/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace impactbench::sensitivity {
namespace {

/// find_contacts margin [m] that lists every potential contact of a small system (the
/// event-driven engine's default too; the planar system rejects an infinite margin).
constexpr double kAllContactsMargin = 1e3;

namespace ed = engines::event_driven;

struct ContactTable {
  std::vector<model::ContactKey> keys;
  std::vector<double> friction;
  int index_of(const model::ContactKey& key) const {
    const auto it = std::find(keys.begin(), keys.end(), key);
    if (it == keys.end())
      throw std::invalid_argument(
          "nominal_from_event_run: an event names a contact the system "
          "does not list");
    return static_cast<int>(it - keys.begin());
  }
};

ContactTable contact_table(const model::LagrangianSystem<double>& system, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v) {
  std::vector<model::Contact<double>> contacts;
  system.find_contacts(q, v, kAllContactsMargin, contacts);
  ContactTable table;
  for (const auto& c : contacts) {
    table.keys.push_back(c.key);
    table.friction.push_back(c.friction);
  }
  return table;
}

/// The phase of a contact in the engine's mode `mode` with sliding velocity ζ_t (slip direction
/// as in the header). `stick_lambda_t` is the stick friction force just before, for slip onset.
/// A spatial slip phase gets its reference direction in `reference`.
ContactPhase phase_of(ed::ContactMode mode, double friction, const Eigen::VectorXd& zeta_t,
                      const Eigen::VectorXd& stick_lambda_t, std::vector<double>& reference) {
  reference.clear();
  if (mode == ed::ContactMode::kOpen) return ContactPhase::kOpen;
  if (friction == 0.0) return ContactPhase::kSlipPositive;
  if (mode == ed::ContactMode::kStick) return ContactPhase::kStick;
  if (zeta_t.size() == 1) {
    const double direction = std::abs(zeta_t(0)) > 1e-12 ? zeta_t(0) : -stick_lambda_t(0);
    return direction >= 0.0 ? ContactPhase::kSlipPositive : ContactPhase::kSlipNegative;
  }
  const Eigen::VectorXd direction =
      zeta_t.norm() > 1e-12 ? zeta_t : Eigen::VectorXd(-stick_lambda_t);
  if (!(direction.norm() > 0.0))
    throw std::invalid_argument(
        "nominal_from_event_run: a contact slips with neither sliding velocity nor friction force "
        "(no slip direction)");
  const Eigen::VectorXd unit = direction.normalized();
  reference.assign(unit.data(), unit.data() + unit.size());
  return ContactPhase::kSlipPositive;
}

GuardKind guard_of(ed::EventKind kind, double t) {
  switch (kind) {
    case ed::EventKind::kImpact:
      return GuardKind::kImpact;
    case ed::EventKind::kLiftoff:
      return GuardKind::kLiftOff;
    case ed::EventKind::kSlipToStick:
    case ed::EventKind::kSlipReversal:
      return GuardKind::kSlipToStick;
    case ed::EventKind::kStickToSlip:
      return GuardKind::kStickToSlip;
    default:
      throw std::invalid_argument(
          "nominal_from_event_run: the " + std::string(ed::to_string(kind)) +
          " event at t = " + output::number_text(t) +
          " s has no first-order jump gain (linearise over a shorter duration, ending before it)");
  }
}

}  // namespace

NominalTrajectory nominal_from_event_run(const MechanicalHybridModel& model,
                                         const model::LagrangianSystem<double>& system,
                                         const ed::EventDrivenResult& run,
                                         const InputFunction& input,
                                         const InputFunction& input_rate, double duration) {
  if (!run.succeeded())
    throw std::invalid_argument("nominal_from_event_run: the run failed: " + run.message);
  if (run.event_states.empty())
    throw std::invalid_argument("nominal_from_event_run: the run has no initial event state");
  const ed::EventState& initial = run.event_states.front();
  const ContactTable table = contact_table(system, initial.q, initial.v);
  const int nc = static_cast<int>(table.keys.size());
  const int m = model.input_size();
  const auto u_at = [&](double t) { return input ? input(t) : Eigen::VectorXd::Zero(m); };

  // Phases of all contacts after an event state (ζ_t at the state; stick forces of `before`).
  const auto phases_at = [&](const ed::EventState& s, const HybridMode& before) {
    const Eigen::VectorXd x = model.state(s.q, s.v);
    const Eigen::MatrixXd zeta = model.relative_velocities(x);
    HybridMode stick_all = before;
    for (auto& p : stick_all)
      if (is_closed(p)) p = ContactPhase::kStick;
    const Eigen::Index d = zeta.cols() - 1;
    Eigen::MatrixXd lambda_t = Eigen::MatrixXd::Zero(nc, d);
    bool need_forces = false;
    for (const auto& [key, mode] : s.modes)
      need_forces = need_forces || (mode == ed::ContactMode::kSlip &&
                                    before[table.index_of(key)] == ContactPhase::kStick);
    if (need_forces) lambda_t = model.mode_forces(before, x, u_at(s.t)).lambda_t;
    HybridMode phases(nc, ContactPhase::kOpen);
    if (d > 1) phases.slip_reference.resize(nc);
    std::vector<double> reference;
    for (const auto& [key, mode] : s.modes) {
      const int i = table.index_of(key);
      phases[i] = phase_of(mode, table.friction[i], zeta.row(i).tail(d).transpose(),
                           lambda_t.row(i).transpose(), reference);
      if (d > 1) phases.slip_reference[i] = reference;
    }
    return phases;
  };

  NominalTrajectory nominal;
  nominal.t_begin = initial.t;
  nominal.t_end = duration;
  nominal.x0 = model.state(initial.q, initial.v);
  nominal.input = input;
  nominal.input_rate = input_rate;
  nominal.mode0 = phases_at(initial, HybridMode(nc, ContactPhase::kOpen));

  HybridMode mode = nominal.mode0;
  for (std::size_t k = 1; k < run.event_states.size(); ++k) {
    const ed::EventState& state = run.event_states[k];
    // The last snapshot of this instant holds its final state and modes.
    if (k + 1 < run.event_states.size() && run.event_states[k + 1].t == state.t) continue;
    std::vector<const ed::Event*> logged;
    for (const ed::Event& e : run.events)
      if (e.t == state.t) logged.push_back(&e);
    if (logged.empty()) continue;
    const HybridMode after = phases_at(state, mode);
    const bool impacts = std::any_of(logged.begin(), logged.end(), [](const ed::Event* e) {
      return e->kind == ed::EventKind::kImpact;
    });
    NominalEvent event;
    event.time = state.t;
    event.x_plus = model.state(state.q, state.v);
    // At an impact instant the impulse may change the phase of other closed contacts (slip
    // reversal, lift-off of an old pivot): that belongs to the impact's reset, not to a guard
    // crossing.
    std::vector<CarriedPhase> carried;
    const auto carry = [&](int i, const std::string& why) {
      if (!(impacts && is_closed(mode[i])))
        throw std::invalid_argument("nominal_from_event_run: contact " + std::to_string(i) +
                                    " changes mode at t = " + output::number_text(state.t) + " s " +
                                    why);
      carried.push_back({i, after[i]});
    };
    for (const ed::Event* e : logged) {
      const int i = table.index_of(e->key);
      const GuardKind kind = guard_of(e->kind, e->t);
      if (impacts && kind != GuardKind::kImpact) {
        const bool impacting_contact = std::any_of(logged.begin(), logged.end(), [&](auto* o) {
          return o->kind == ed::EventKind::kImpact && o->key == e->key;
        });
        // Follow-on mode decisions of an impacting contact are its impact's phase_after.
        if (impacting_contact || after[i] == mode[i]) continue;
        carry(i, "through another contact's impact (not a guard crossing) into " +
                     std::string(to_string(after[i])));
        continue;
      }
      MicroEvent micro{i, kind, after[i], {}};
      micro.slip_reference = after.reference(i);
      if (kind == GuardKind::kImpact && !is_closed(after[i]) && table.friction[i] > 0.0) {
        // A bounce: the impulse's tangential law as the engine chose it by Γ (B.25); a planar
        // slip impulse Λ_t = −μ Λ_n s gives s = −sign Λ_t; a spatial one (Coulomb law, its
        // direction solved by the model) is marked slip+.
        const bool spatial = e->impulse_t.size() > 1;
        const double lambda_t = e->impulse_t.size() > 0 ? e->impulse_t(0) : 0.0;
        micro.bounce_impulse = e->impact_map == ed::ContactMode::kStick ? ContactPhase::kStick
                               : spatial ? (e->impulse_t.norm() > 0.0 ? ContactPhase::kSlipPositive
                                                                      : ContactPhase::kOpen)
                               : lambda_t < 0.0 ? ContactPhase::kSlipPositive
                               : lambda_t > 0.0 ? ContactPhase::kSlipNegative
                                                : ContactPhase::kOpen;
      }
      event.micro_events.push_back(micro);
    }
    // Contacts that did not log an event keep their phase, or carry the impact's change.
    for (int i = 0; i < nc; ++i) {
      const bool listed = std::any_of(event.micro_events.begin(), event.micro_events.end(),
                                      [&](const MicroEvent& me) { return me.contact == i; }) ||
                          std::any_of(carried.begin(), carried.end(),
                                      [&](const CarriedPhase& c) { return c.contact == i; });
      if (!listed && after[i] != mode[i]) carry(i, "without an event");
    }
    if (!carried.empty()) {
      if (event.micro_events.size() != 1)
        throw std::invalid_argument(
            "nominal_from_event_run: at t = " + output::number_text(state.t) +
            " s simultaneous impacts change the phase of another closed contact (not supported)");
      event.micro_events.front().carried = std::move(carried);
    }
    for (const MicroEvent& me : event.micro_events) mode = apply_event(mode, me);
    nominal.events.push_back(std::move(event));
  }
  return nominal;
}

}  // namespace impactbench::sensitivity
