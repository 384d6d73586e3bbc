#include "lib/engines/event_driven/event_driven_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include "lib/engines/event_driven/constrained_flow.hpp"
#include "lib/engines/event_driven/cvode_session.hpp"
#include "lib/engines/event_driven/impact_map.hpp"
#include "lib/engines/event_driven/mode_consistency.hpp"
#include "lib/engines/run_timer.hpp"
#include "lib/output/message_text.hpp"

namespace impactbench::engines::event_driven {
namespace {

using model::Contact;
using model::ContactKey;

/// Why a guard fired (root or watchdog).
enum class Guard { kGap, kLiftoff, kSlipToStick, kStickToSlip };

struct TrackedContact {
  ContactMode mode = ContactMode::kOpen;
  Eigen::VectorXd slip_reference;
  int impacts_in_row = 0;  ///< consecutive impacts, reset by a lift-off (Zeno detection)
};

void validate(const EventDrivenOptions& o) {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("event-driven options: " + what);
  };
  if (!(o.relative_tolerance > 0.0) || !(o.absolute_tolerance > 0.0))
    fail("relative_tolerance and absolute_tolerance must be > 0");
  if (!(o.output_interval >= 0.0)) fail("output_interval must be >= 0");
  if (o.max_events <= 0) fail("max_events must be > 0");
  if (o.max_events_per_instant <= 0) fail("max_events_per_instant must be > 0");
  if (!(o.contact_margin > 0.0)) fail("contact_margin must be > 0");
  if (!(o.gap_tolerance > 0.0) || !(o.velocity_tolerance > 0.0) ||
      !(o.complementarity_tolerance > 0.0))
    fail("gap, velocity and complementarity tolerances must be > 0");
  if (o.zeno_impact_count <= 0) fail("zeno_impact_count must be > 0");
  if (!(o.zeno_velocity >= 0.0) || !(o.zeno_min_interval >= 0.0))
    fail("zeno_velocity and zeno_min_interval must be >= 0");
  if (!(o.max_step >= 0.0)) fail("max_step must be >= 0");
  if (!(o.initial_step >= 0.0)) fail("initial_step must be >= 0");
  if (!(o.startup_step_growth > 1.0)) fail("startup_step_growth must be > 1");
  if (o.startup_order < 0) fail("startup_order must be >= 0");
  if (!(o.nonlinear_convergence_coefficient > 0.0))
    fail("nonlinear_convergence_coefficient must be > 0");
}

// One simulate() call: the hybrid state and the bookkeeping of the run.
class Run {
 public:
  Run(const model::LagrangianSystem<double>& system, const EventDrivenOptions& options,
      const EventDrivenIntegrator::Input& input, const EventDrivenIntegrator::Observer& observer,
      EventDrivenResult& result)
      : system_(system),
        options_(options),
        input_(input),
        observer_(observer),
        result_(result),
        nq_(system.num_positions()),
        nv_(system.num_velocities()) {}

  void execute(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double duration);

 private:
  // --- state helpers
  Eigen::VectorXd input_at(double t) const {
    if (system_.num_inputs() == 0) return Eigen::VectorXd(0);
    if (!input_) return Eigen::VectorXd::Zero(system_.num_inputs());
    Eigen::VectorXd u = input_(t);
    if (u.size() != system_.num_inputs())
      throw std::invalid_argument("event-driven: input u(t) has size " + std::to_string(u.size()) +
                                  ", the system has " + std::to_string(system_.num_inputs()) +
                                  " inputs");
    // A non-finite force cannot be integrated: stop instead of letting CVODE shrink its step.
    if (!u.allFinite())
      throw std::invalid_argument("event-driven: input u(t) is not finite at t = " +
                                  output::number_text(t));
    return u;
  }
  void find_contacts(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                     std::vector<Contact<double>>& out) const {
    system_.find_contacts(q, v, options_.contact_margin, out);
  }
  static const Contact<double>* lookup(const std::vector<Contact<double>>& contacts,
                                       const ContactKey& key) {
    for (const auto& c : contacts)
      if (c.key == key) return &c;
    return nullptr;
  }
  // The same, looking first at `hint`: the system lists contacts in a fixed order, so while
  // the contact set of a segment is unchanged the k-th slot is the k-th contact. Without the
  // hint every guard evaluation was a search per slot: (pairs)² per right-hand side, N⁴ in
  // the number of balls of a cradle.
  static const Contact<double>* lookup(const std::vector<Contact<double>>& contacts,
                                       const ContactKey& key, std::size_t hint) {
    if (hint < contacts.size() && contacts[hint].key == key) return &contacts[hint];
    return lookup(contacts, key);
  }
  TrackedContact& tracked(const ContactKey& key) { return tracked_[key]; }
  ContactMode mode_of(const ContactKey& key) const {
    const auto it = tracked_.find(key);
    return it == tracked_.end() ? ContactMode::kOpen : it->second.mode;
  }
  std::vector<ClosedContact> closed_list(const std::vector<Contact<double>>& contacts) const {
    std::vector<ClosedContact> closed;
    for (const auto& c : contacts) {
      const auto it = tracked_.find(c.key);
      if (it == tracked_.end() || it->second.mode == ContactMode::kOpen) continue;
      closed.push_back({&c, it->second.mode, it->second.slip_reference});
    }
    return closed;
  }
  Eigen::VectorXd normalized_positions(const Eigen::VectorXd& q) const {
    // Unit quaternions drift under q̇ = N(q)v; integrate_position keeps them unit. The flow is
    // evaluated at the normalised q, so the drift of the norm never reaches the dynamics, and
    // the state is renormalised at every event.
    if (nq_ == nv_) return q;
    return system_.integrate_position(q, Eigen::VectorXd::Zero(nv_), 0.0);
  }
  // state_q_, state_v_ = the (normalised) state y = (q, v) of a right-hand side or guard
  // evaluation, in buffers kept across CVODE's calls (no allocation per call).
  void load_state(const Eigen::Ref<const Eigen::VectorXd>& y) {
    if (nq_ == nv_)
      state_q_ = y.head(nq_);
    else
      state_q_ = normalized_positions(y.head(nq_));
    state_v_ = y.tail(nv_);
  }

  // Removes the drift of the closed contacts' constraints (the flow enforces them only at
  // acceleration level): the least M-norm corrections with h_n = 0 and ζ_n = 0 (and ζ_t = 0
  // when sticking). Done at every event, so drift never accumulates over segments.
  void project_onto_closed_constraints(Eigen::VectorXd& q, Eigen::VectorXd& v) const {
    std::vector<Contact<double>> contacts;
    for (int pass = 0; pass < 2; ++pass) {
      find_contacts(q, v, contacts);
      const auto closed = closed_list(contacts);
      if (closed.empty()) return;
      Eigen::MatrixXd Wn(nv_, static_cast<Eigen::Index>(closed.size()));
      Eigen::VectorXd gaps(Wn.cols());
      for (std::size_t i = 0; i < closed.size(); ++i) {
        Wn.col(static_cast<Eigen::Index>(i)) = closed[i].contact->normal_direction(nv_);
        gaps[static_cast<Eigen::Index>(i)] = closed[i].contact->gap;
      }
      q = system_.integrate_position(q, least_norm_correction(q, Wn, gaps), 1.0);
    }
    find_contacts(q, v, contacts);
    const auto closed = closed_list(contacts);
    std::vector<Eigen::VectorXd> rows;
    for (const auto& c : closed) {
      rows.push_back(c.contact->normal_direction(nv_));
      if (c.mode == ContactMode::kStick) {
        const Eigen::MatrixXd Wt = c.contact->tangent_directions(nv_);
        for (Eigen::Index k = 0; k < Wt.cols(); ++k) rows.push_back(Wt.col(k));
      }
    }
    Eigen::MatrixXd A(nv_, static_cast<Eigen::Index>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) A.col(static_cast<Eigen::Index>(i)) = rows[i];
    v += least_norm_correction(q, A, A.transpose() * v);
  }
  // δ minimising δᵀMδ with Jᵀδ = −r (least squares when redundant).
  Eigen::VectorXd least_norm_correction(const Eigen::VectorXd& q, const Eigen::MatrixXd& J,
                                        const Eigen::VectorXd& r) const {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(system_.mass_matrix(q));
    const Eigen::MatrixXd MinvJ = ldlt.solve(J);
    const Eigen::MatrixXd D = J.transpose() * MinvJ;
    return -MinvJ * D.completeOrthogonalDecomposition().solve(r);
  }

  // --- flow and guards
  struct FlowAt {
    std::vector<Contact<double>> contacts;
    std::vector<ClosedContact> closed;
    FlowSolution flow;
    double force_scale = 1.0;
  };
  void evaluate_flow(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                     FlowAt& at) const {
    find_contacts(q, v, at.contacts);
    const DynamicsAtState dynamics(system_, q, v, input_at(t));
    at.closed = closed_list(at.contacts);
    at.flow = solve_constrained_flow(dynamics, v, at.closed, 1e-10);
    at.force_scale = 1.0 + dynamics.free_force().cwiseAbs().maxCoeff();
  }
  // What the guards need at a state of the current segment: the contacts, and the flow's
  // forces only when some contact is closed (the guards of open contacts are their gaps).
  void evaluate_guard_inputs(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    if (!segment_open_) return evaluate_flow(t, q, v, scratch_);
    find_contacts(q, v, scratch_.contacts);
    scratch_.closed.clear();
  }
  void rhs(double t, const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> ydot) {
    load_state(y);
    const Eigen::VectorXd &q = state_q_, &v = state_v_;
    if (segment_open_) {
      // No closed contact: the free flow M⁻¹ f, without looking for contacts.
      const DynamicsAtState dynamics(system_, q, v, input_at(t));
      ydot.head(nq_) = system_.position_rate(q, v);
      ydot.tail(nv_) = dynamics.solve(dynamics.free_force());
      return;
    }
    guards_cached_ = false;  // scratch_ changes
    evaluate_flow(t, q, v, scratch_);
    if (!scratch_.flow.ok) {
      ydot.setConstant(std::numeric_limits<double>::quiet_NaN());
      flow_failed_ = true;
      return;
    }
    ydot.head(nq_) = system_.position_rate(q, v);
    ydot.tail(nv_) = scratch_.flow.vdot;
  }
  // Two root functions per slot (see the header); unused ones are constant 1.
  void guards(double t, const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> g) {
    g = guard_values_at(t, y);
  }
  // The guard values at (t, y), with scratch_ holding what they were computed from. CVODE
  // evaluates the guards at the end of every step and at every root it returns, where
  // check_guards and add_guards_at_zero look at them again: those reuse the last evaluation.
  const Eigen::VectorXd& guard_values_at(double t, const Eigen::Ref<const Eigen::VectorXd>& y) {
    if (guards_cached_ && t == guards_t_ && (y.array() == guards_y_.array()).all())
      return guards_g_;
    load_state(y);
    const Eigen::VectorXd &q = state_q_, &v = state_v_;
    evaluate_guard_inputs(t, q, v);
    guards_g_.resize(approach_index() + 1);
    guard_values(scratch_, v, guards_g_);
    guards_t_ = t;
    guards_y_ = y;
    guards_cached_ = true;
    return guards_g_;
  }
  void guard_values(const FlowAt& at, const Eigen::VectorXd& v,
                    Eigen::Ref<Eigen::VectorXd> g) const {
    g.setOnes();
    std::size_t tracked_found = 0;
    // Index of each contact's flow force (at.closed points into at.contacts).
    std::vector<int>& closed_index = closed_index_scratch_;
    closed_index.assign(at.contacts.size(), -1);
    for (std::size_t j = 0; j < at.closed.size(); ++j)
      closed_index[static_cast<std::size_t>(at.closed[j].contact - at.contacts.data())] =
          static_cast<int>(j);
    for (std::size_t k = 0; k < slots_.size(); ++k) {
      const Contact<double>* c = lookup(at.contacts, slots_[k], k);
      const auto i = static_cast<Eigen::Index>(2 * k);
      if (c == nullptr) {
        g[i] = options_.contact_margin;
        continue;
      }
      ++tracked_found;
      const ContactMode mode = mode_of(c->key);
      if (mode == ContactMode::kOpen) {
        g[i] = c->gap;
        continue;
      }
      const auto j =
          static_cast<std::size_t>(closed_index[static_cast<std::size_t>(c - at.contacts.data())]);
      const ContactForce& force = at.flow.forces[j];
      g[i] = force.lambda_n;
      const double mu = c->friction;
      if (mode == ContactMode::kStick) {
        g[i + 1] = (mu * mu * force.lambda_n * force.lambda_n - force.lambda_t.squaredNorm());
      } else if (mu > 0.0) {
        const Eigen::VectorXd zeta_t = c->relative_velocity(v).tail(c->tangent_dim());
        g[i + 1] = zeta_t.dot(tracked_.at(c->key).slip_reference);
      }
    }
    if (g.size() > 2 * static_cast<Eigen::Index>(slots_.size()))
      g[g.size() - 1] = approach_guard(at.contacts, tracked_found);
  }
  // The last root function: min over the contacts without a slot of gap − margin/2 (margin/2
  // when there is none; continuous, since a contact enters the list at gap = margin). It
  // reaches zero before any untracked pair can touch, whatever the speeds, so a small margin
  // tracks only the pairs near contact and the segment restarts when another comes close.
  double approach_guard(const std::vector<Contact<double>>& contacts,
                        std::size_t tracked_found) const {
    const double half = 0.5 * options_.contact_margin;
    double g = half;
    if (tracked_found == contacts.size()) return g;
    for (const auto& c : contacts)
      if (!slot_keys_.contains(c.key)) g = std::min(g, c.gap - half);
    return g;
  }
  Eigen::Index approach_index() const { return 2 * static_cast<Eigen::Index>(slots_.size()); }
  // Size below which a guard value counts as zero: a guard that starts a segment at zero
  // (e.g. ζ_t right after stick→slip, which grows like (t − t*)²) is not armed until it has
  // moved past this, so that CVODE's roots of its round-off are ignored.
  double guard_threshold(Eigen::Index index, ContactMode mode, double force_scale) const {
    const bool first = index % 2 == 0;
    if (mode == ContactMode::kOpen) return options_.gap_tolerance;
    if (first) return options_.complementarity_tolerance * force_scale;
    if (mode == ContactMode::kStick)
      return options_.complementarity_tolerance * force_scale * force_scale;
    return options_.velocity_tolerance;
  }
  // Arms the guards that moved clear of zero, and returns the guards already on the wrong side
  // (a root CVODE cannot see because the guard started at zero); empty when all is well.
  std::map<ContactKey, Guard> check_guards(double t, const Eigen::VectorXd& y) {
    const Eigen::VectorXd& g = guard_values_at(t, y);
    const Eigen::VectorXd v = y.tail(nv_);
    if (g[approach_index()] > 0.0) armed_[static_cast<std::size_t>(approach_index())] = true;
    std::map<ContactKey, Guard> out;
    for (std::size_t k = 0; k < slots_.size(); ++k) {
      const ContactMode mode = mode_of(slots_[k]);
      for (Eigen::Index i = 2 * static_cast<Eigen::Index>(k);
           i < 2 * static_cast<Eigen::Index>(k) + 2; ++i) {
        const double threshold = guard_threshold(i, mode, scratch_.force_scale);
        if (g[i] > threshold) armed_[static_cast<std::size_t>(i)] = true;
        if (g[i] < -threshold && !out.count(slots_[k]) && !separating(i, mode, slots_[k], v))
          out[slots_[k]] = guard_kind(i, mode);
      }
    }
    return out;
  }
  // Armed guards within their threshold of zero at an event cross at the same instant (to the
  // tolerance): e.g. the second corner of a block reaching the friction limit.
  void add_guards_at_zero(double t, const Eigen::VectorXd& y, std::map<ContactKey, Guard>& fired) {
    const Eigen::VectorXd& g = guard_values_at(t, y);
    const Eigen::VectorXd v = y.tail(nv_);
    for (Eigen::Index i = 0; i < approach_index(); ++i) {
      const ContactKey& key = slots_[static_cast<std::size_t>(i / 2)];
      const ContactMode mode = mode_of(key);
      if (armed_[static_cast<std::size_t>(i)] && !fired.count(key) &&
          std::abs(g[i]) <= guard_threshold(i, mode, scratch_.force_scale))
        fired[key] = guard_kind(i, mode);
    }
  }
  // An open contact below its surface (by constraint drift) that already moves apart needs no
  // event.
  bool separating(Eigen::Index index, ContactMode mode, const ContactKey& key,
                  const Eigen::VectorXd& v) const {
    if (mode != ContactMode::kOpen || index % 2 != 0) return false;
    const Contact<double>* c = lookup(scratch_.contacts, key);
    return c != nullptr && c->relative_velocity(v)[0] >= 0.0;
  }
  static Guard guard_kind(Eigen::Index index, ContactMode mode) {
    if (index % 2 == 0) return mode == ContactMode::kOpen ? Guard::kGap : Guard::kLiftoff;
    return mode == ContactMode::kStick ? Guard::kStickToSlip : Guard::kSlipToStick;
  }
  // Roots reported by CVODE on armed guards.
  std::map<ContactKey, Guard> fired_guards(const std::vector<int>& roots) const {
    std::map<ContactKey, Guard> out;
    for (std::size_t i = 0; i + 1 < roots.size(); ++i) {
      if (roots[i] == 0 || !armed_[i]) continue;
      const ContactKey& key = slots_[i / 2];
      if (!out.count(key)) out[key] = guard_kind(static_cast<Eigen::Index>(i), mode_of(key));
    }
    return out;
  }

  // --- events
  bool process_instant(double t, Eigen::VectorXd& q, Eigen::VectorXd& v,
                       const std::map<ContactKey, Guard>& fired, bool initial);
  bool apply_impacts(double t, const Eigen::VectorXd& q, Eigen::VectorXd& v,
                     const std::vector<Contact<double>>& contacts, bool initial);
  double predicted_impact_interval(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                   const ContactKey& key, const std::vector<ContactKey>& closing);
  void log_event(Event event) {
    ++result_.summary.counts[static_cast<int>(event.kind)];
    result_.events.push_back(std::move(event));
  }
  Event make_event(double t, const Contact<double>& c, EventKind kind, ContactMode from,
                   ContactMode to) const {
    Event e;
    e.t = t;
    e.contact = c.name;
    e.key = c.key;
    e.kind = kind;
    e.from_mode = from;
    e.to_mode = to;
    e.impulse_t = Eigen::VectorXd::Zero(c.tangent_dim());
    return e;
  }
  void fail(SimulationStatus status, std::string message) {
    if (result_.status == SimulationStatus::kSuccess) {
      result_.status = status;
      result_.message = std::move(message);
    }
  }

  // --- output
  void emit_sample(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                   const Eigen::Ref<const Eigen::VectorXd>& v) {
    last_sample_time_ = t;
    if (!observer_) {
      // Kept in the result, as part of the integration: timing it apart would cost two reads
      // of the process CPU clock (system calls), more than the sample itself.
      result_.samples.push_back(make_sample(t, q, v));
      return;
    }
    const auto recording = timer_.scoped(RunTimer::Phase::kRecord);
    observer_(make_sample(t, q, v));
  }
  Sample make_sample(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                     const Eigen::Ref<const Eigen::VectorXd>& v) const {
    Sample s;
    s.t = t;
    s.q = nq_ == nv_ ? Eigen::VectorXd(q) : normalized_positions(q);
    s.v = v;
    s.energy = system_.energy(s.q, s.v);
    return s;
  }
  void emit_samples_until(double t_reached, const CvodeSession& session) {
    if (options_.output_interval <= 0.0) return;
    while (next_sample_ <= t_reached + 1e-14 * std::max(1.0, std::abs(t_reached)) &&
           next_sample_ < t_end_) {
      const auto y = session.interpolate(std::min(next_sample_, t_reached));
      emit_sample(next_sample_, y.head(nq_), y.tail(nv_));
      ++sample_index_;
      next_sample_ = static_cast<double>(sample_index_) * options_.output_interval;
    }
  }

  const model::LagrangianSystem<double>& system_;
  const EventDrivenOptions& options_;
  const EventDrivenIntegrator::Input& input_;
  const EventDrivenIntegrator::Observer& observer_;
  EventDrivenResult& result_;
  RunTimer timer_;  // the observer's samples are recording, the rest integration
  const int nq_, nv_;
  std::map<ContactKey, TrackedContact> tracked_;
  std::vector<ContactKey> slots_;   // contacts with root functions in the current segment
  std::set<ContactKey> slot_keys_;  // the same, for the approach guard's lookups
  std::vector<bool> armed_;         // per root function: has moved clear of zero
  FlowAt scratch_;
  Eigen::VectorXd state_q_, state_v_;  // load_state's buffers
  bool segment_open_ = false;          // every contact open in the current segment (free flight)
  bool guards_cached_ = false;         // guards_g_ = guard values at (guards_t_, guards_y_)
  double guards_t_ = 0.0;
  Eigen::VectorXd guards_y_, guards_g_;
  mutable std::vector<int> closed_index_scratch_;  // guard_values' map contact → closed force
  bool flow_failed_ = false;
  double t_end_ = 0.0;
  double next_sample_ = 0.0;
  long sample_index_ = 0;
  double last_sample_time_ = -std::numeric_limits<double>::infinity();
  double last_instant_ = -1.0;
  int events_at_instant_ = 0;
};

double Run::predicted_impact_interval(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                      const ContactKey& key,
                                      const std::vector<ContactKey>& closing) {
  // Ballistic estimate 2ζ_n/|a_n| of the next flight of this contact, with the contacts that
  // stay closed held fixed (stick): only the size of the normal acceleration matters here.
  std::vector<Contact<double>> contacts;
  find_contacts(q, v, contacts);
  const Contact<double>* c = lookup(contacts, key);
  if (c == nullptr) return std::numeric_limits<double>::infinity();
  std::vector<ClosedContact> closed;
  for (const auto& other : contacts)
    for (const auto& k : closing)
      if (other.key == k) closed.push_back({&other, ContactMode::kStick, Eigen::VectorXd()});
  const DynamicsAtState dynamics(system_, q, v, input_at(t));
  const FlowSolution flow = solve_constrained_flow(dynamics, v, closed, 1e-10);
  const ContactFrame frame = ContactFrame::of(*c, nv_);
  const double zeta_n = frame.J.col(0).dot(v);
  const double accel_n = frame.J.col(0).dot(flow.vdot) + frame.drift[0];
  if (!(accel_n < 0.0)) return std::numeric_limits<double>::infinity();
  return 2.0 * zeta_n / -accel_n;
}

bool Run::apply_impacts(double t, const Eigen::VectorXd& q, Eigen::VectorXd& v,
                        const std::vector<Contact<double>>& contacts, bool initial) {
  // Moreau's impact law acts on every contact closed at the instant: the closing ones, the
  // closed ones and the open ones that merely touch (a row of touching balls struck at one end
  // takes the blow together, not pair by pair). A touching contact enters with e min(ζ_n⁻, 0)
  // = 0 (impact_map.cpp) and keeps its mode here: the mode decision below settles it.
  std::vector<const Contact<double>*> participants;
  std::vector<bool> impacting, touching;
  for (const auto& c : contacts) {
    const ContactMode mode = mode_of(c.key);
    const bool open_at_surface = mode == ContactMode::kOpen && c.gap <= options_.gap_tolerance;
    const bool closing =
        open_at_surface && c.relative_velocity(v)[0] < -options_.velocity_tolerance;
    if (open_at_surface || mode != ContactMode::kOpen) {
      participants.push_back(&c);
      impacting.push_back(closing);
      touching.push_back(open_at_surface && !closing);
    }
  }
  bool any = false;
  for (bool b : impacting) any = any || b;
  if (!any) return true;

  const DynamicsAtState dynamics(system_, q, v, input_at(t));
  std::vector<double> restitution;
  for (const auto* c : participants) restitution.push_back(c->restitution);
  auto solve = [&]() {
    if (participants.size() == 1)
      return single_contact_impact(dynamics, v, *participants[0], restitution[0], options_);
    return simultaneous_impact(dynamics, v, participants, restitution, options_);
  };
  ImpactResult impact = solve();
  if (!impact.ok) {
    fail(SimulationStatus::kContactSolverFailure, impact.message);
    return false;
  }
  // Zeno: contacts that would bounce again after a vanishing interval rest instead.
  std::vector<bool> zeno(participants.size(), false);
  std::vector<double> accumulation(participants.size(), 0.0);
  {
    std::vector<ContactKey> closing_keys;
    for (std::size_t i = 0; i < participants.size(); ++i)
      if (impact.contacts[i].zeta_after[0] <= options_.velocity_tolerance)
        closing_keys.push_back(participants[i]->key);
    bool any_zeno = false;
    for (std::size_t i = 0; i < participants.size(); ++i) {
      const double zeta_after = impact.contacts[i].zeta_after[0];
      if (!impacting[i] || zeta_after <= options_.velocity_tolerance) continue;
      const double interval =
          predicted_impact_interval(t, q, impact.v_plus, participants[i]->key, closing_keys);
      const int count = tracked_[participants[i]->key].impacts_in_row + 1;
      if (interval < options_.zeno_min_interval ||
          (count >= options_.zeno_impact_count && zeta_after < options_.zeno_velocity)) {
        zeno[i] = true;
        any_zeno = true;
        const double e = restitution[i];
        accumulation[i] = e < 1.0 && std::isfinite(interval) ? t + interval / (1.0 - e) : t;
        restitution[i] = 0.0;
      }
    }
    if (any_zeno) {
      impact = solve();
      if (!impact.ok) {
        fail(SimulationStatus::kContactSolverFailure, impact.message);
        return false;
      }
    }
  }
  v = impact.v_plus;
  for (std::size_t i = 0; i < participants.size(); ++i) {
    if (touching[i]) continue;
    const Contact<double>& c = *participants[i];
    const ContactImpulse& ci = impact.contacts[i];
    TrackedContact& state = tracked(c.key);
    const ContactMode from = state.mode;
    const bool closes = ci.zeta_after[0] <= options_.velocity_tolerance;
    const int d = c.tangent_dim();
    ContactMode to = ContactMode::kOpen;
    if (closes) {
      to = ci.map;
      if (to == ContactMode::kSlip) {
        const Eigen::VectorXd zeta_t = ci.zeta_after.tail(d);
        state.slip_reference = zeta_t.norm() > 0.0 ? Eigen::VectorXd(zeta_t.normalized())
                                                   : Eigen::VectorXd::Unit(d, 0);
      }
    }
    state.mode = to;
    if (!impacting[i] && to != ContactMode::kOpen) continue;  // stays closed: modes settle below
    EventKind kind = EventKind::kLiftoff;
    if (impacting[i]) kind = zeno[i] ? EventKind::kZenoRest : EventKind::kImpact;
    if (impacting[i])
      state.impacts_in_row = zeno[i] ? 0 : state.impacts_in_row + 1;
    else
      state.impacts_in_row = 0;
    if (initial && !impacting[i]) continue;
    Event e = make_event(t, c, kind, from, to);
    e.impulse_n = ci.impulse[0];
    e.impulse_t = ci.impulse.tail(d);
    e.normal_velocity_before = ci.zeta_before[0];
    e.normal_velocity_after = ci.zeta_after[0];
    e.impact_map = impacting[i] ? ci.map : ContactMode::kOpen;
    e.gamma = ci.gamma;
    e.accumulation_time = accumulation[i];
    log_event(std::move(e));
  }
  return true;
}

bool Run::process_instant(double t, Eigen::VectorXd& q, Eigen::VectorXd& v,
                          const std::map<ContactKey, Guard>& fired, bool initial) {
  if (t == last_instant_) {
    if (++events_at_instant_ > options_.max_events_per_instant) {
      fail(SimulationStatus::kStalled,
           "event-driven: no progress in time at t = " + std::to_string(t) +
               " s (events keep firing at one instant)");
      return false;
    }
  } else {
    last_instant_ = t;
    events_at_instant_ = 0;
  }
  q = normalized_positions(q);
  project_onto_closed_constraints(q, v);
  // Samples at an event instant: the state entering it (after the drift projection, i.e. what
  // the jump maps act on), then the state leaving it.
  if (!initial && options_.sample_events) emit_sample(t, q, v);
  const Eigen::VectorXd v_before = v;
  std::vector<Contact<double>> contacts;
  find_contacts(q, v, contacts);
  // Stick forces just before the event: a stick→slip contact slips against them.
  FlowAt before;
  if (std::any_of(fired.begin(), fired.end(),
                  [](const auto& guard) { return guard.second == Guard::kStickToSlip; }))
    evaluate_flow(t, q, v, before);

  if (!apply_impacts(t, q, v, contacts, initial)) return false;
  find_contacts(q, v, contacts);  // v may have jumped: drift terms change

  std::vector<ModeCandidate> candidates;
  for (const auto& c : contacts) {
    const ContactMode mode = mode_of(c.key);
    const double zeta_n = c.relative_velocity(v)[0];
    const bool touching = mode == ContactMode::kOpen && c.gap <= options_.gap_tolerance &&
                          std::abs(zeta_n) <= options_.velocity_tolerance;
    if (mode == ContactMode::kOpen && !touching) continue;
    ModeCandidate candidate;
    candidate.contact = &c;
    const auto f = fired.find(c.key);
    if (f != fired.end() && f->second == Guard::kLiftoff) {
      candidate.hint = ModeCandidate::Hint::kPreferOpen;
    } else if (f != fired.end() && f->second == Guard::kStickToSlip &&
               mode == ContactMode::kStick) {
      for (std::size_t j = 0; j < before.closed.size(); ++j) {
        if (before.closed[j].contact->key != c.key) continue;
        const Eigen::VectorXd& lambda_t = before.flow.forces[j].lambda_t;
        if (lambda_t.norm() > 0.0) {
          candidate.hint = ModeCandidate::Hint::kForceSlip;
          candidate.forced_slip_direction = -lambda_t.normalized();
        }
      }
    }
    candidates.push_back(std::move(candidate));
  }
  const DynamicsAtState dynamics(system_, q, v, input_at(t));
  const ModeConsistencyResult consistent = make_modes_consistent(dynamics, v, candidates, options_);
  if (!consistent.ok) {
    fail(SimulationStatus::kContactSolverFailure, consistent.message);
    return false;
  }
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Contact<double>& c = *candidates[i].contact;
    const ModeDecision& decision = consistent.decisions[i];
    TrackedContact& state = tracked(c.key);
    const ContactMode from = state.mode;
    const ContactMode to = decision.mode;
    const bool reversed = from == ContactMode::kSlip && to == ContactMode::kSlip &&
                          c.friction > 0.0 && state.slip_reference.size() == c.tangent_dim() &&
                          decision.slip_reference.dot(state.slip_reference) < 0.0;
    state.mode = to;
    if (to == ContactMode::kSlip) state.slip_reference = decision.slip_reference;
    if (to == ContactMode::kOpen) state.impacts_in_row = 0;
    if (initial || (from == to && !reversed)) continue;
    EventKind kind = EventKind::kTouchdown;
    if (to == ContactMode::kOpen)
      kind = EventKind::kLiftoff;
    else if (from == ContactMode::kOpen)
      kind = EventKind::kTouchdown;
    else if (to == ContactMode::kStick)
      kind = EventKind::kSlipToStick;
    else if (from == ContactMode::kStick)
      kind = EventKind::kStickToSlip;
    else
      kind = EventKind::kSlipReversal;
    log_event(make_event(t, c, kind, from, to));
  }
  EventState snapshot;
  snapshot.t = t;
  snapshot.q = q;
  snapshot.v = v;
  snapshot.v_before = v_before;
  for (const auto& [key, state] : tracked_)
    if (state.mode != ContactMode::kOpen) snapshot.modes[key] = state.mode;
  result_.event_states.push_back(std::move(snapshot));
  if (static_cast<int>(result_.events.size()) >= options_.max_events) {
    fail(SimulationStatus::kMaxEvents,
         "event-driven: reached max_events = " + std::to_string(options_.max_events) +
             " at t = " + std::to_string(t) + " s");
    return false;
  }
  return true;
}

void Run::execute(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double duration) {
  timer_.start(RunTimer::Phase::kEngine);
  t_end_ = duration;
  Eigen::VectorXd q = q0, v = v0;
  double t = 0.0;
  CvodeSession session(
      nq_ + nv_, options_,
      [this](double tt, const Eigen::Ref<const Eigen::VectorXd>& y,
             Eigen::Ref<Eigen::VectorXd> yd) { rhs(tt, y, yd); },
      [this](double tt, const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> g) {
        guards(tt, y, g);
      });
  emit_sample(0.0, q, v);
  sample_index_ = 1;
  next_sample_ = options_.output_interval;
  bool alive = process_instant(t, q, v, {}, /*initial=*/true);
  if (alive && options_.sample_events && !result_.events.empty()) emit_sample(t, q, v);

  Eigen::VectorXd y(nq_ + nv_);
  while (alive && t < t_end_) {
    std::vector<Contact<double>> contacts;
    find_contacts(q, v, contacts);
    slots_.clear();
    for (const auto& c : contacts) slots_.push_back(c.key);
    slot_keys_ = std::set<ContactKey>(slots_.begin(), slots_.end());
    y << q, v;
    session.restart(t, y, 2 * static_cast<int>(slots_.size()) + 1, t_end_);
    armed_.assign(2 * slots_.size() + 1, false);
    guards_cached_ = false;  // new slots and modes
    segment_open_ = std::none_of(tracked_.begin(), tracked_.end(), [](const auto& entry) {
      return entry.second.mode != ContactMode::kOpen;
    });
    check_guards(t, y);
    ++result_.summary.segments;
    result_.summary.max_tracked_contacts =
        std::max(result_.summary.max_tracked_contacts, static_cast<long>(slots_.size()));
    flow_failed_ = false;
    bool restart = false;
    while (!restart) {
      const auto outcome = session.step();
      if (outcome == CvodeSession::StepOutcome::kFailure) {
        fail(flow_failed_ ? SimulationStatus::kSingularDynamics
                          : SimulationStatus::kIntegratorFailure,
             session.failure_message() + " at t = " + std::to_string(session.time()) +
                 (flow_failed_ ? " s (constrained dynamics without solution)" : " s"));
        alive = false;
        break;
      }
      t = session.time();
      emit_samples_until(t, session);
      y = session.state();
      q = y.head(nq_);
      v = y.tail(nv_);
      if (outcome == CvodeSession::StepOutcome::kReachedEnd || t >= t_end_) {
        restart = true;
        break;
      }
      std::map<ContactKey, Guard> fired;
      if (outcome == CvodeSession::StepOutcome::kRoot) {
        const std::vector<int> roots = session.roots_found();
        fired = fired_guards(roots);
        if (fired.empty()) {
          // An untracked pair came within half the margin: track it from here.
          if (roots.back() != 0 && armed_.back()) restart = true;
          continue;  // otherwise a root of an unarmed guard's round-off
        }
        add_guards_at_zero(t, y, fired);
      } else {
        fired = check_guards(t, y);
        if (fired.empty()) {
          // A contact entering the tracking margin needs its own root functions (the
          // approach guard normally restarts first); one that left keeps its slot.
          find_contacts(q, v, contacts);
          for (const auto& c : contacts)
            if (!slot_keys_.contains(c.key)) restart = true;
          continue;
        }
      }
      alive = process_instant(t, q, v, fired, /*initial=*/false);
      if (alive && options_.sample_events) emit_sample(t, q, v);
      restart = true;
    }
    result_.summary.rhs_evaluations += session.rhs_evaluations();
    result_.summary.root_evaluations += session.root_evaluations();
    result_.summary.steps += session.steps();
  }
  if (alive) {
    if (last_sample_time_ < t_end_) emit_sample(t_end_, q, v);
  }
  result_.final_time = t;
  result_.q = normalized_positions(q);
  result_.v = v;
  timer_.stop();
  result_.summary.engine_cpu_seconds = timer_.engine_cpu_seconds();
  result_.summary.record_cpu_seconds = timer_.record_cpu_seconds();
  result_.summary.wall_seconds = timer_.wall_seconds();
}

}  // namespace

EventDrivenIntegrator::EventDrivenIntegrator(const model::LagrangianSystem<double>& system,
                                             EventDrivenOptions options)
    : system_(system), options_(std::move(options)) {
  validate(options_);
}

EventDrivenResult EventDrivenIntegrator::simulate(const Eigen::VectorXd& q0,
                                                  const Eigen::VectorXd& v0, const Input& input,
                                                  double duration, const Observer& observer) const {
  if (q0.size() != system_.num_positions() || v0.size() != system_.num_velocities())
    throw std::invalid_argument("event-driven: initial state has sizes (" +
                                std::to_string(q0.size()) + ", " + std::to_string(v0.size()) +
                                "), the system needs (" + std::to_string(system_.num_positions()) +
                                ", " + std::to_string(system_.num_velocities()) + ")");
  if (!q0.allFinite() || !v0.allFinite())
    throw std::invalid_argument("event-driven: initial state is not finite");
  if (!(duration > 0.0) || !std::isfinite(duration))
    throw std::invalid_argument("event-driven: duration must be a finite positive time");
  EventDrivenResult result;
  Run run(system_, options_, input, observer, result);
  run.execute(q0, v0, duration);
  return result;
}

}  // namespace impactbench::engines::event_driven
