#include "lib/sensitivity/conewise_jump_gain.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace impactbench::sensitivity {

ConewiseJumpGain::ConewiseJumpGain(const HybridModel& model, const HybridMode& mode,
                                   std::vector<MicroEvent> events, const Eigen::VectorXd& x_minus,
                                   const Eigen::VectorXd& u, const Eigen::VectorXd& u_rate)
    : events_(std::move(events)), mode_before_(mode), x_minus_(x_minus) {
  if (events_.empty() || events_.size() > 5)
    throw std::invalid_argument("ConewiseJumpGain: a macro event needs 1 to 5 micro events, got " +
                                std::to_string(events_.size()));
  std::vector<int> path;
  build(model, path, mode, x_minus, u, u_rate);
  std::vector<int> listed(events_.size());
  std::iota(listed.begin(), listed.end(), 0);
  const ComposedGain nominal = gain_of_order(listed);
  x_plus_ = nominal.x_plus;
  mode_after_ = nominal.mode_after;
}

void ConewiseJumpGain::build(const HybridModel& model, std::vector<int>& path,
                             const HybridMode& mode, const Eigen::VectorXd& x,
                             const Eigen::VectorXd& u, const Eigen::VectorXd& u_rate) {
  for (int k = 0; k < static_cast<int>(events_.size()); ++k) {
    if (std::find(path.begin(), path.end(), k) != path.end()) continue;
    path.push_back(k);
    MicroEventLinearisation lin = linearise_micro_event(model, mode, events_[k], x, u, u_rate);
    const HybridMode next_mode = lin.mode_after;
    const Eigen::VectorXd next_x = lin.x_plus;
    paths_.emplace(path, std::move(lin));
    build(model, path, next_mode, next_x, u, u_rate);
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
      const JumpGain& g = micro_event(candidate).gain;
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
  std::vector<int> order(events_.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<ComposedGain> out;
  do {
    out.push_back(gain_of_order(order));
  } while (std::next_permutation(order.begin(), order.end()));
  return out;
}

double ConewiseJumpGain::order_dependence() const {
  double worst = 0.0;
  for (const ComposedGain& g : all_gains())
    worst = std::max(worst, (g.x_plus - x_plus_).lpNorm<Eigen::Infinity>());
  return worst;
}

}  // namespace impactbench::sensitivity
