#include "lib/sensitivity/jump_gain.hpp"
#include "lib/output/number_text.hpp"

#include <stdexcept>
#include <string>

namespace impactbench::sensitivity {

JumpGain compute_jump_gain(const Eigen::VectorXd& f_minus, const Eigen::VectorXd& f_plus,
                           const Eigen::MatrixXd& reset_jacobian, const GuardLinearisation& guard,
                           const Eigen::VectorXd& input_rate) {
  const Eigen::Index n = f_minus.size();
  const Eigen::Index m = input_rate.size();
  if (f_plus.size() != n || reset_jacobian.rows() != n || reset_jacobian.cols() != n ||
      guard.dx.size() != n || guard.du.size() != m)
    throw std::invalid_argument("compute_jump_gain: inconsistent sizes (n = " + std::to_string(n) +
                                ", m = " + std::to_string(m) + ")");
  // γ̇ = D_xγ f⁻ + D_uγ μ̇ (C.24 without explicit time dependence).
  const double state_rate = guard.dx.dot(f_minus);
  const double input_term = m > 0 ? guard.du.dot(input_rate) : 0.0;
  const double rate = state_rate + input_term;
  const double scale =
      guard.dx.norm() * f_minus.norm() + (m > 0 ? guard.du.norm() * input_rate.norm() : 0.0);
  if (!(rate < -1e-12 * scale) || scale == 0.0)
    throw std::runtime_error("compute_jump_gain: the guard is not crossed transversally (rate " +
                             output::number_text(rate) + ", scale " + output::number_text(scale) +
                             ")");
  JumpGain gain;
  gain.guard_rate = rate;
  gain.a = -guard.dx / rate;
  gain.b = -guard.du / rate;
  // z⁺ = D_xg z⁻ − (f⁺ − D_xg f⁻) Δ with Δ = a z⁻ + b v  (header derivation).
  const Eigen::VectorXd jump_of_rate = f_plus - reset_jacobian * f_minus;
  gain.Gz = reset_jacobian - jump_of_rate * gain.a;
  gain.Gv = -jump_of_rate * gain.b;
  return gain;
}

MicroEventLinearisation linearise_micro_event(const HybridModel& model, const HybridMode& mode,
                                              const MicroEvent& event,
                                              const Eigen::VectorXd& x_minus,
                                              const Eigen::VectorXd& u,
                                              const Eigen::VectorXd& u_rate) {
  MicroEventLinearisation out;
  out.event = event;
  out.mode_before = mode;
  out.mode_after = apply_event(mode, event);
  out.x_minus = x_minus;
  out.guard = model.linearise_guard(mode, event, x_minus, u);
  const ResetLinearisation reset = model.linearise_reset(mode, event, x_minus);
  out.x_plus = reset.x_plus;
  out.f_minus = model.flow(mode, x_minus, u);
  out.f_plus = model.flow(out.mode_after, out.x_plus, u);
  out.gain = compute_jump_gain(out.f_minus, out.f_plus, reset.dx, out.guard, u_rate);
  return out;
}

}  // namespace impactbench::sensitivity
