#pragma once
// The jump gain of a macro event: several guards crossed at the same nominal instant τ
// (simultaneous impacts of C_L and C_R, an impact followed at once by a mode change). Source
// C.2 and D.1–D.12.
//
// Composition (C.40–C.42, with the text's C.41 corrected: the input term of the second jump is
// G_v^{k+} v, not G_z^{k+} v). For micro events k then k+, each linearised at the intermediate
// nominal state α^k (the state after the earlier micro jumps, at the same τ) and the mode s^k,
//     z^{k+} = G_z^{k+} (G_z^k z^{k−} + G_v^k v) + G_v^{k+} v.
// The input perturbation is continuous in time, so every micro event sees the same v = v(τ).
//
// Ordering (D.2–D.8). A perturbation splits the macro event into micro events at
// τ + ε Δ^η, Δ^η = a^η z + b^η v. Their order is that of Δ: from the current intermediate mode
// the next micro event is η* = argmin_η (a^η z^k + b^η v) over the guards not yet crossed (D.8),
// with a^η, b^η of D.7 evaluated at α^k, s^k. Each order gives one linear gain, so the map
// H(z, v) is conewise linear: constant on the cones bounded by the hyperplanes of D.10, and
// positively homogeneous, H(a z, a v) = a H(z, v) for a > 0 (D.13–D.22). On a border the two
// orders' results coincide when the nominal post-event state does not depend on the order (e.g.
// inelastic impacts, whose jump maps are nested projections); ties go to the lower index.
//
// Coincident guards. Two non-impact micro events of the same kind and target phase whose
// shifts coincide, a^η = a^ζ and b^η = b^ζ (to 1e-8 relative), cross at the same perturbed time
// to first order for every (z, v); e.g. the two bottom corners of a sliding box stop together.
// After one of them alone the other's guard is not crossed transversally (the box is already at
// rest), so they switch together: the first one's gain uses the joint mode change, the second
// follows at once with the identity gain (MicroEventLinearisation::joined). Only orders that keep
// such partners adjacent exist.
//
// All orders are linearised eagerly (n! paths for n micro events; n ≤ 5 is enforced).
#include <map>
#include <vector>

#include <Eigen/Core>

#include "lib/sensitivity/jump_gain.hpp"

namespace impactbench::sensitivity {

/// The linear gain of one order of micro events: z⁺ = Gz z⁻ + Gv v.
struct ComposedGain {
  std::vector<int> order;  ///< indices into the macro event's micro events
  Eigen::MatrixXd Gz, Gv;
  Eigen::VectorXd x_plus;  ///< nominal post-event state reached by this order
  HybridMode mode_after;
};

class ConewiseJumpGain {
 public:
  /// Linearises every order of `events` (all at time τ from state x_minus in `mode`) with input
  /// u = μ(τ), rate u_rate = μ̇(τ). Throws std::invalid_argument for an empty list or more than
  /// five micro events, and whatever linearise_micro_event throws (non-transversal guards).
  ConewiseJumpGain(const HybridModel& model, const HybridMode& mode, std::vector<MicroEvent> events,
                   const Eigen::VectorXd& x_minus, const Eigen::VectorXd& u,
                   const Eigen::VectorXd& u_rate);

  const std::vector<MicroEvent>& events() const { return events_; }
  const HybridMode& mode_before() const { return mode_before_; }
  const Eigen::VectorXd& x_minus() const { return x_minus_; }

  /// The order of micro events that the perturbation (z⁻, v) selects (D.8).
  std::vector<int> order_for(const Eigen::VectorXd& z, const Eigen::VectorXd& v) const;
  /// H(z⁻, v) = z⁺ with the selected order (D.9).
  Eigen::VectorXd apply(const Eigen::VectorXd& z, const Eigen::VectorXd& v) const;
  /// The gain of one order (a permutation of 0..n−1). Throws std::invalid_argument for an order
  /// that separates coincident micro events.
  ComposedGain gain_of_order(const std::vector<int>& order) const;
  /// Gains of every existing order, in lexicographic order of the permutations.
  std::vector<ComposedGain> all_gains() const;
  /// The micro event linearisation reached along `path` (its last index is the micro event).
  const MicroEventLinearisation& micro_event(const std::vector<int>& path) const;

  /// The nominal post-event state and mode (the listed order 0, 1, ...,
  /// or the first existing one).
  const Eigen::VectorXd& x_plus() const { return x_plus_; }
  const HybridMode& mode_after() const { return mode_after_; }
  /// max over orders of ‖x⁺(order) − x⁺(listed order)‖∞: zero when the macro event is well posed.
  double order_dependence() const;

 private:
  void build(const HybridModel& model, std::vector<int>& path, const HybridMode& mode,
             const Eigen::VectorXd& x, const Eigen::VectorXd& u, const Eigen::VectorXd& u_rate,
             std::vector<int> joined);

  std::vector<MicroEvent> events_;
  HybridMode mode_before_, mode_after_;
  Eigen::VectorXd x_minus_, x_plus_;
  std::map<std::vector<int>, MicroEventLinearisation> paths_;
  double first_rate_ = 0.0;  ///< largest |guard rate| of the micro events that can come first
};

}  // namespace impactbench::sensitivity
