#include "lib/engines/event_driven/guard_set.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impactbench::engines::event_driven {
namespace {

using model::Contact;
using model::ContactKey;

Guard guard_kind(Eigen::Index index, ContactMode mode) {
  if (index % 2 == 0) return mode == ContactMode::kOpen ? Guard::kGap : Guard::kLiftoff;
  return mode == ContactMode::kStick ? Guard::kStickToSlip : Guard::kSlipToStick;
}

}  // namespace

void GuardSet::begin_segment(const std::vector<Contact<double>>& contacts) {
  slots_.clear();
  for (const auto& c : contacts) slots_.push_back(c.key);
  slot_keys_ = std::set<ContactKey>(slots_.begin(), slots_.end());
  armed_.assign(2 * slots_.size() + 1, false);
  cache_.valid = false;  // new slots and modes
}

bool GuardSet::tracks_all_checked() const {
  const std::vector<model::ContactGap>& gaps = flow_.scratch().gaps;
  return std::all_of(gaps.begin(), gaps.end(),
                     [this](const model::ContactGap& c) { return slot_keys_.contains(c.key); });
}

// The cache key is the exact (t, y): only a repeated evaluation at the same state may reuse it.
const Eigen::VectorXd& GuardSet::values_at(double t, const Eigen::Ref<const Eigen::VectorXd>& y) {
  if (cache_.valid && cache_.version == flow_.scratch_version() && t == cache_.t &&
      (y.array() == cache_.y.array()).all())
    return cache_.g;
  flow_.evaluate_guard_inputs(t, y);
  cache_.g.resize(approach_index() + 1);
  guard_values(flow_.scratch(), flow_.velocity(), cache_.g);
  cache_.t = t;
  cache_.y = y;
  cache_.version = flow_.scratch_version();
  cache_.valid = true;
  return cache_.g;
}

void GuardSet::guard_values(const FlowAt& at, const Eigen::VectorXd& v,
                            Eigen::Ref<Eigen::VectorXd> g) const {
  g.setOnes();
  std::size_t tracked_found = 0;
  // Index of each contact's flow force (at.closed points into at.contacts).
  closed_index_.assign(at.gaps.size(), -1);
  for (std::size_t j = 0; j < at.closed.size(); ++j)
    closed_index_[static_cast<std::size_t>(at.closed[j].contact - at.contacts.data())] =
        static_cast<int>(j);
  for (std::size_t k = 0; k < slots_.size(); ++k) {
    const std::ptrdiff_t found = index_of_key(at.gaps, slots_[k], k);
    const auto i = static_cast<Eigen::Index>(2 * k);
    if (found < 0) {
      g[i] = run_.options.contact_margin;
      continue;
    }
    ++tracked_found;
    const auto index = static_cast<std::size_t>(found);
    const ContactMode mode = modes_.mode_of(slots_[k]);
    if (mode == ContactMode::kOpen) {
      g[i] = at.gaps[index].gap;
      continue;
    }
    // A closed contact: the segment's flow found the whole contacts (SegmentFlow only skips
    // them while every contact is open).
    if (!at.contacts_current)
      throw std::logic_error("guard values: a closed contact without its contact data");
    const Contact<double>* c = &at.contacts[index];
    const auto j = static_cast<std::size_t>(closed_index_[index]);
    const ContactForce& force = at.flow.forces[j];
    g[i] = force.lambda_n;
    const double mu = c->friction;
    if (mode == ContactMode::kStick) {
      g[i + 1] = (mu * mu * force.lambda_n * force.lambda_n - force.lambda_t.squaredNorm());
    } else if (mu > 0.0) {
      const Eigen::VectorXd zeta_t = c->relative_velocity(v).tail(c->tangent_dim());
      g[i + 1] = zeta_t.dot(modes_.slip_reference(c->key));
    }
  }
  if (g.size() > 2 * static_cast<Eigen::Index>(slots_.size()))
    g[g.size() - 1] = approach_guard(at.gaps, tracked_found);
}

// The last root function: min over the contacts without a slot of gap − margin/2 (margin/2
// when there is none; continuous, since a contact enters the list at gap = margin). It reaches
// zero before any untracked pair can touch, whatever the speeds, so a small margin tracks only
// the pairs near contact and the segment restarts when another comes close.
double GuardSet::approach_guard(const std::vector<model::ContactGap>& gaps,
                                std::size_t tracked_found) const {
  const double half = 0.5 * run_.options.contact_margin;
  double g = half;
  if (tracked_found == gaps.size()) return g;
  for (const auto& c : gaps)
    if (!slot_keys_.contains(c.key)) g = std::min(g, c.gap - half);
  return g;
}

// Size below which a guard value counts as zero: a guard that starts a segment at zero (e.g.
// ζ_t right after stick→slip, which grows like (t − t*)²) is not armed until it has moved past
// this.
double GuardSet::threshold(Eigen::Index index, ContactMode mode, double force_scale) const {
  const EventDrivenOptions& o = run_.options;
  const bool first = index % 2 == 0;
  if (mode == ContactMode::kOpen) return o.gap_tolerance;
  if (first) return o.complementarity_tolerance * force_scale;
  if (mode == ContactMode::kStick) return o.complementarity_tolerance * force_scale * force_scale;
  return o.velocity_tolerance;
}

FiredGuards GuardSet::check(double t, const Eigen::VectorXd& y) {
  const Eigen::VectorXd& g = values_at(t, y);
  if (g[approach_index()] > 0.0) armed_[static_cast<std::size_t>(approach_index())] = true;
  FiredGuards out;
  for (std::size_t k = 0; k < slots_.size(); ++k) {
    const ContactMode mode = modes_.mode_of(slots_[k]);
    for (Eigen::Index i = 2 * static_cast<Eigen::Index>(k);
         i < 2 * static_cast<Eigen::Index>(k) + 2; ++i) {
      const double limit = threshold(i, mode, flow_.scratch().force_scale);
      if (g[i] > limit) armed_[static_cast<std::size_t>(i)] = true;
      if (g[i] < -limit && !out.count(slots_[k]) && !separating(i, mode, slots_[k], y))
        out[slots_[k]] = guard_kind(i, mode);
    }
  }
  return out;
}

void GuardSet::add_guards_at_zero(double t, const Eigen::VectorXd& y, FiredGuards& fired) {
  const Eigen::VectorXd& g = values_at(t, y);
  for (Eigen::Index i = 0; i < approach_index(); ++i) {
    const ContactKey& key = slots_[static_cast<std::size_t>(i / 2)];
    const ContactMode mode = modes_.mode_of(key);
    if (armed_[static_cast<std::size_t>(i)] && !fired.count(key) &&
        std::abs(g[i]) <= threshold(i, mode, flow_.scratch().force_scale))
      fired[key] = guard_kind(i, mode);
  }
}

// An open contact below its surface (by constraint drift) that already moves apart needs no
// event.
bool GuardSet::separating(Eigen::Index index, ContactMode mode, const ContactKey& key,
                          const Eigen::VectorXd& y) {
  if (mode != ContactMode::kOpen || index % 2 != 0) return false;
  const Contact<double>* c = find_contact(flow_.guard_contacts(y), key);
  return c != nullptr && c->relative_velocity(y.tail(run_.nv))[0] >= 0.0;
}

bool GuardSet::all_armed() const {
  return std::all_of(armed_.begin(), armed_.end(), [](bool armed) { return armed; });
}

FiredGuards GuardSet::fired_by(const std::vector<int>& roots) const {
  FiredGuards out;
  for (std::size_t i = 0; i + 1 < roots.size(); ++i) {
    if (roots[i] == 0 || !armed_[i]) continue;
    const ContactKey& key = slots_[i / 2];
    if (!out.count(key)) out[key] = guard_kind(static_cast<Eigen::Index>(i), modes_.mode_of(key));
  }
  return out;
}

}  // namespace impactbench::engines::event_driven
