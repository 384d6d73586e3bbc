#pragma once
// The smooth flow between events: CVODE's right-hand side ẏ = (q̇(q, v), v̇) under the current
// contact modes, and what the guards read at a state (the contacts and, when some contact is
// closed, the flow's forces).
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/constrained_flow.hpp"
#include "lib/engines/event_driven/contact_modes.hpp"
#include "lib/engines/event_driven/run_context.hpp"

namespace impactbench::engines::event_driven {

/// The contacts at one state, the closed ones, the flow of their modes and the force scale
/// 1 + ‖f‖∞ the guards' thresholds are relative to; with the flow solve's storage, kept for the
/// next state. For the guards (SegmentFlow::evaluate_guard_inputs) also the contacts' gaps at
/// their state, and whether `contacts` are at that state too (not when only the gaps were
/// found, or a right-hand side evaluated the flow since).
struct FlowAt {
  std::vector<model::ContactGap> gaps;
  bool contacts_current = true;
  std::vector<model::Contact<double>> contacts;
  std::vector<ClosedContact> closed;
  FlowSolution flow;
  double force_scale = 1.0;
  FlowWorkspace workspace;
};

/// Fills `at` at (t, q, v) under the current modes.
void evaluate_flow(const RunContext& run, const ContactModes& modes, double t,
                   const Eigen::VectorXd& q, const Eigen::VectorXd& v, FlowAt& at);

class SegmentFlow {
 public:
  SegmentFlow(const RunContext& run, const ContactModes& modes)
      : run_(run),
        modes_(modes),
        constant_free_flow_(run.system.bias_forces_are_constant() &&
                            run.system.mass_matrix_is_constant() && run.system.num_inputs() == 0) {}

  /// At a segment's start: free flight when every contact is open; no failure yet.
  void begin_segment();
  /// CVODE's right-hand side. A flow without solution (inconsistent modes) gives NaN and sets
  /// failed().
  void rhs(double t, const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> ydot);
  /// Loads y and evaluates what the guards need there: the gaps alone while every contact is
  /// open, else the contacts and their flow. The result stays in scratch() until the next call
  /// or right-hand side.
  void evaluate_guard_inputs(double t, const Eigen::Ref<const Eigen::VectorXd>& y);
  /// The whole contacts at the state of scratch()'s gaps, y: found now if only the gaps were.
  const std::vector<model::Contact<double>>& guard_contacts(
      const Eigen::Ref<const Eigen::VectorXd>& y);
  const FlowAt& scratch() const { return scratch_; }
  /// v of the last state loaded.
  const Eigen::VectorXd& velocity() const { return state_v_; }
  /// Changes whenever scratch() is overwritten by a right-hand side (the guards' cache key).
  unsigned long scratch_version() const { return scratch_version_; }
  bool failed() const { return failed_; }

 private:
  // state_q_, state_v_ = the (normalised) state y = (q, v), in buffers kept across CVODE's
  // calls (no allocation per call).
  void load_state(const Eigen::Ref<const Eigen::VectorXd>& y);

  const RunContext& run_;
  const ContactModes& modes_;
  FlowAt scratch_;
  Eigen::VectorXd state_q_, state_v_;
  Eigen::VectorXd free_force_;  // f of the open flow
  // M⁻¹ f of the open flow, formed once per run when neither M nor f depends on the state or
  // the time (free planar bodies under gravity): then v̇ is the same at every right-hand side.
  const bool constant_free_flow_;
  bool free_acceleration_known_ = false;
  Eigen::VectorXd free_acceleration_;
  bool open_ = false;    // every contact open in the current segment (free flight)
  bool failed_ = false;  // a right-hand side found no flow
  unsigned long scratch_version_ = 0;
};

}  // namespace impactbench::engines::event_driven
