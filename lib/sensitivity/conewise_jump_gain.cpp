#include "lib/sensitivity/conewise_jump_gain.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

namespace impactbench::sensitivity {

ConewiseJumpGain::ConewiseJumpGain(const HybridModel& model, const HybridMode& mode,
                                   std::vector<MicroEvent> events, const Eigen::VectorXd& x_minus,
                                   const Eigen::VectorXd& u, const Eigen::VectorXd& u_rate)
    : events_(std::move(events)), mode_before_(mode), x_minus_(x_minus) {
  if (events_.empty() || events_.size() > 5)
    throw std::invalid_argument("ConewiseJumpGain: a macro event needs 1 to 5 micro events, got " +
                                std::to_string(events_.size()));
  std::vector<int> path;
  build(model, path, mode, x_minus, u, u_rate, {});
  // The listed order where it exists (ties of order_for go to the lower index).
  const ComposedGain nominal = gain_of_order(
      order_for(Eigen::VectorXd::Zero(x_minus.size()), Eigen::VectorXd::Zero(u.size())));
  x_plus_ = nominal.x_plus;
  mode_after_ = nominal.mode_after;
}

namespace {

/// Whether micro events p and q, linearised from the same mode and state, switch together
/// (header: coincident guards). The shifts are compared on `tangent`, a basis of the
/// perturbations that keep the mode's closed contacts closed (the only ones a trajectory of the
/// mode carries): off it, e.g. for a tilt of a box lying flat, the guards may differ.
bool coincident(const MicroEventLinearisation& p, const MicroEventLinearisation& q,
                const Eigen::MatrixXd& tangent) {
  if (p.event.kind == GuardKind::kImpact || p.event.kind != q.event.kind ||
      p.event.phase_after != q.event.phase_after)
    return false;
  const auto close = [](const Eigen::RowVectorXd& x, const Eigen::RowVectorXd& y) {
    return (x - y).norm() <= 1e-8 * std::max(x.norm(), y.norm());
  };
  return close(p.gain.a * tangent, q.gain.a * tangent) && close(p.gain.b, q.gain.b);
}

/// A basis of the null space of the mode's constraint rows at x (identity without closed
/// contacts).
Eigen::MatrixXd tangent_basis(const HybridModel& model, const HybridMode& mode,
                              const Eigen::VectorXd& x) {
  const Eigen::MatrixXd C = model.mode_constraint_rows(mode, x);
  if (C.rows() == 0) return Eigen::MatrixXd::Identity(x.size(), x.size());
  const Eigen::MatrixXd kernel = Eigen::FullPivLU<Eigen::MatrixXd>(C).kernel();
  // Eigen returns one zero column for a trivial kernel: nothing to restrict to then.
  if (kernel.isZero(0.0)) return Eigen::MatrixXd::Identity(x.size(), x.size());
  return kernel;
}

}  // namespace

void ConewiseJumpGain::build(const HybridModel& model, std::vector<int>& path,
                             const HybridMode& mode, const Eigen::VectorXd& x,
                             const Eigen::VectorXd& u, const Eigen::VectorXd& u_rate,
                             std::vector<int> joined) {
  if (!joined.empty()) {
    // A partner of the previous micro event: already switched, identity gain.
    const int k = joined.front();
    joined.erase(joined.begin());
    const MicroEventLinearisation& previous = paths_.at(path);
    MicroEventLinearisation lin = previous;
    lin.event = events_[k];
    lin.mode_before = lin.mode_after;
    lin.x_minus = lin.x_plus;
    lin.f_minus = lin.f_plus;
    lin.gain.Gz = Eigen::MatrixXd::Identity(x.size(), x.size());
    lin.gain.Gv = Eigen::MatrixXd::Zero(x.size(), u.size());
    lin.joined = true;
    path.push_back(k);
    paths_.emplace(path, std::move(lin));
    build(model, path, mode, x, u, u_rate, joined);
    path.pop_back();
    return;
  }
  std::map<int, MicroEventLinearisation> pending;
  for (int k = 0; k < static_cast<int>(events_.size()); ++k)
    if (std::find(path.begin(), path.end(), k) == path.end())
      pending.emplace(k, linearise_micro_event(model, mode, events_[k], x, u, u_rate));
  if (path.empty()) {
    for (const auto& [k, single] : pending)
      first_rate_ = std::max(first_rate_, std::abs(single.gain.guard_rate));
  } else {
    // A guard that the earlier micro events have already brought to rest (the fourth corner of
    // a face landing flat: its gap is a combination of the three others') has a rate of
    // round-off size; compute_jump_gain's test, relative to a flow that is itself at rest, lets
    // it through and the gain would divide by round-off. Its gain does not exist (C.37).
    for (const auto& [k, single] : pending)
      if (!(std::abs(single.gain.guard_rate) > 1e-9 * first_rate_))
        throw std::runtime_error(
            "ConewiseJumpGain: micro event " + std::to_string(k) + " (" + to_string(events_[k]) +
            ") is no longer crossed transversally after micro event " +
            std::to_string(path.back()) +
            ": its contact is held by the others already (a redundant contact, as the fourth "
            "corner of a face landing flat); such simultaneous events are not linearised");
  }
  const Eigen::MatrixXd tangent =
      pending.size() > 1 ? tangent_basis(model, mode, x) : Eigen::MatrixXd();
  for (auto& [k, single] : pending) {
    std::vector<int> partners;
    HybridMode joint_mode = single.mode_after;
    for (const auto& [l, other] : pending)
      if (l != k && coincident(single, other, tangent)) {
        partners.push_back(l);
        joint_mode = apply_event(joint_mode, other.event);
      }
    MicroEventLinearisation lin = single;
    if (!partners.empty()) {
      // One guard (this one's), the joint mode change, identity reset (non-impact).
      lin.mode_after = joint_mode;
      lin.f_plus = model.flow(joint_mode, lin.x_plus, u);
      lin.gain =
          compute_jump_gain(lin.f_minus, lin.f_plus, Eigen::MatrixXd::Identity(x.size(), x.size()),
                            lin.guard, u_rate);
    }
    const HybridMode next_mode = lin.mode_after;
    const Eigen::VectorXd next_x = lin.x_plus;
    path.push_back(k);
    paths_.emplace(path, std::move(lin));
    build(model, path, next_mode, next_x, u, u_rate, partners);
    path.pop_back();
  }
}

const MicroEventLinearisation& ConewiseJumpGain::micro_event(const std::vector<int>& path) const {
  const auto it = paths_.find(path);
  if (it == paths_.end())
    throw std::invalid_argument("ConewiseJumpGain: no micro event along the given path");
  return it->second;
}

std::vector<int> ConewiseJumpGain::order_for(const Eigen::VectorXd& z,
                                             const Eigen::VectorXd& v) const {
  std::vector<int> path;
  Eigen::VectorXd zk = z;
  while (path.size() < events_.size()) {
    int best = -1;
    double best_shift = 0.0;
    for (int k = 0; k < static_cast<int>(events_.size()); ++k) {
      if (std::find(path.begin(), path.end(), k) != path.end()) continue;
      std::vector<int> candidate = path;
      candidate.push_back(k);
      const auto it = paths_.find(candidate);
      if (it == paths_.end()) continue;  // a coincident partner must come first
      const JumpGain& g = it->second.gain;
      // D.8: the time shift Δ = a z + b v of this guard from the current intermediate mode.
      const double shift = g.a.dot(zk) + (v.size() > 0 ? g.b.dot(v) : 0.0);
      if (best < 0 || shift < best_shift) {
        best = k;
        best_shift = shift;
      }
    }
    path.push_back(best);
    const JumpGain& g = micro_event(path).gain;
    zk = g.Gz * zk + (v.size() > 0 ? Eigen::VectorXd(g.Gv * v) : Eigen::VectorXd::Zero(zk.size()));
  }
  return path;
}

Eigen::VectorXd ConewiseJumpGain::apply(const Eigen::VectorXd& z, const Eigen::VectorXd& v) const {
  const ComposedGain gain = gain_of_order(order_for(z, v));
  Eigen::VectorXd out = gain.Gz * z;
  if (v.size() > 0) out += gain.Gv * v;
  return out;
}

ComposedGain ConewiseJumpGain::gain_of_order(const std::vector<int>& order) const {
  if (order.size() != events_.size())
    throw std::invalid_argument("ConewiseJumpGain: an order must list every micro event");
  ComposedGain out;
  out.order = order;
  std::vector<int> path;
  for (const int k : order) {
    path.push_back(k);
    const MicroEventLinearisation& lin = micro_event(path);
    if (path.size() == 1) {
      out.Gz = lin.gain.Gz;
      out.Gv = lin.gain.Gv;
    } else {
      // C.42 (C.41 corrected): the later jump's own input gain enters as G_v^{k+} v.
      out.Gv = lin.gain.Gz * out.Gv + lin.gain.Gv;
      out.Gz = lin.gain.Gz * out.Gz;
    }
    out.x_plus = lin.x_plus;
    out.mode_after = lin.mode_after;
  }
  return out;
}

std::vector<ComposedGain> ConewiseJumpGain::all_gains() const {
  std::vector<ComposedGain> out;
  for (const auto& [path, lin] : paths_)  // lexicographic
    if (path.size() == events_.size()) out.push_back(gain_of_order(path));
  return out;
}

double ConewiseJumpGain::order_dependence() const {
  double worst = 0.0;
  for (const ComposedGain& g : all_gains())
    worst = std::max(worst, (g.x_plus - x_plus_).lpNorm<Eigen::Infinity>());
  return worst;
}

}  // namespace impactbench::sensitivity
