#include "lib/engines/event_driven/segment_flow.hpp"

#include <limits>

namespace impactbench::engines::event_driven {

void evaluate_flow(const RunContext& run, const ContactModes& modes, double t,
                   const Eigen::VectorXd& q, const Eigen::VectorXd& v, FlowAt& at) {
  run.find_contacts(q, v, at.contacts);
  const DynamicsAtState dynamics = run.dynamics_at(t, q, v);
  modes.closed_among(at.contacts, at.closed);
  solve_constrained_flow(dynamics, v, at.closed, run.options, at.workspace, at.flow);
  at.force_scale = 1.0 + dynamics.free_force().cwiseAbs().maxCoeff();
}

void SegmentFlow::begin_segment() {
  open_ = modes_.all_open();
  failed_ = false;
}

void SegmentFlow::load_state(const Eigen::Ref<const Eigen::VectorXd>& y) {
  if (run_.nq == run_.nv)
    state_q_ = y.head(run_.nq);
  else
    state_q_ = run_.normalized_positions(y.head(run_.nq));
  state_v_ = y.tail(run_.nv);
}

void SegmentFlow::rhs(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                      Eigen::Ref<Eigen::VectorXd> ydot) {
  load_state(y);
  const Eigen::VectorXd &q = state_q_, &v = state_v_;
  if (open_) {
    // No closed contact: the free flow M⁻¹ f, without looking for contacts (f in kept storage).
    run_.system.write_position_rate(q, v, ydot.head(run_.nq));
    if (constant_free_flow_ && free_acceleration_known_) {
      ydot.tail(run_.nv) = free_acceleration_;
      return;
    }
    model::write_free_force(run_.system, q, v, run_.input_at(t), free_force_);
    run_.solve_mass(q, free_force_, ydot.tail(run_.nv));
    if (constant_free_flow_) {
      free_acceleration_ = ydot.tail(run_.nv);
      free_acceleration_known_ = true;
    }
    return;
  }
  ++scratch_version_;
  evaluate_flow(run_, modes_, t, q, v, scratch_);
  scratch_.contacts_current = false;  // at this state, not at the guards' (gaps)
  if (!scratch_.flow.ok) {
    ydot.setConstant(std::numeric_limits<double>::quiet_NaN());
    failed_ = true;
    return;
  }
  run_.system.write_position_rate(q, v, ydot.head(run_.nq));
  ydot.tail(run_.nv) = scratch_.flow.vdot;
}

void SegmentFlow::evaluate_guard_inputs(double t, const Eigen::Ref<const Eigen::VectorXd>& y) {
  load_state(y);
  if (!open_) {
    evaluate_flow(run_, modes_, t, state_q_, state_v_, scratch_);
    model::write_contact_gaps(scratch_.contacts, scratch_.gaps);
    scratch_.contacts_current = true;
    return;
  }
  // The guards of open contacts are their gaps: the rest of each contact is found only if asked
  // for (guard_contacts).
  run_.system.find_contact_gaps(state_q_, state_v_, run_.options.contact_margin, scratch_.gaps);
  scratch_.contacts_current = false;
  scratch_.closed.clear();
}

const std::vector<model::Contact<double>>& SegmentFlow::guard_contacts(
    const Eigen::Ref<const Eigen::VectorXd>& y) {
  if (!scratch_.contacts_current) {
    load_state(y);
    run_.find_contacts(state_q_, state_v_, scratch_.contacts);
    scratch_.contacts_current = true;
  }
  return scratch_.contacts;
}

}  // namespace impactbench::engines::event_driven
