#pragma once
// What the sensitivity module needs from a hybrid system, linearised at one point: the mode's
// vector field f_s(x, u) with A = D_x f, B = D_u f (C.5, D.14–D.15); a guard γ(x, u) with its
// gradients (C.17–C.24); a reset map g(x) with D_x g (C.7). The system is autonomous given the
// input u(t): time enters only through u, so D_t γ = D_t g = 0 and the input-rate term of C.24
// carries all explicit time dependence. Jump maps do not depend on u (C.27: impulsive inputs do
// not exist).
//
// The state is x = (q, v). Implementations: MechanicalHybridModel (Lagrangian systems with
// unilateral contacts, Jacobians by forward-mode AD) and small analytic test systems.
#include <Eigen/Core>

#include "lib/sensitivity/hybrid_mode.hpp"

namespace impactbench::sensitivity {

struct FlowLinearisation {
  Eigen::VectorXd f;  ///< ẋ = f_s(x, u), size n
  Eigen::MatrixXd A;  ///< D_x f, n × n
  Eigen::MatrixXd B;  ///< D_u f, n × m
};

struct GuardLinearisation {
  double value = 0.0;     ///< γ(x, u), > 0 inside the mode
  Eigen::RowVectorXd dx;  ///< D_x γ, 1 × n
  Eigen::RowVectorXd du;  ///< D_u γ, 1 × m
};

struct ResetLinearisation {
  Eigen::VectorXd x_plus;  ///< g(x⁻)
  Eigen::MatrixXd dx;      ///< D_x g, n × n
};

class HybridModel {
 public:
  virtual ~HybridModel() = default;

  virtual int state_size() const = 0;  ///< n
  virtual int input_size() const = 0;  ///< m
  virtual int num_contacts() const = 0;

  /// f_s(x, u) only (cheap; used to integrate nominal and perturbed trajectories).
  virtual Eigen::VectorXd flow(const HybridMode& mode, const Eigen::VectorXd& x,
                               const Eigen::VectorXd& u) const = 0;
  virtual FlowLinearisation linearise_flow(const HybridMode& mode, const Eigen::VectorXd& x,
                                           const Eigen::VectorXd& u) const = 0;

  /// The guard of `event` for a trajectory in `mode` (event.contact's phase in `mode` must be
  /// the one the guard ends).
  virtual GuardLinearisation linearise_guard(const HybridMode& mode, const MicroEvent& event,
                                             const Eigen::VectorXd& x,
                                             const Eigen::VectorXd& u) const = 0;

  /// The reset map of `event` from `mode` (identity for non-impact events).
  virtual ResetLinearisation linearise_reset(const HybridMode& mode, const MicroEvent& event,
                                             const Eigen::VectorXd& x) const = 0;

  /// Rows C (k × n) whose null space holds the perturbations z that keep the closed contacts
  /// of `mode` closed to first order (gap and normal velocity, plus tangential velocity when
  /// sticking). Initial perturbations must satisfy C z = 0 for the flow of `mode` to apply.
  virtual Eigen::MatrixXd mode_constraint_rows(const HybridMode& mode,
                                               const Eigen::VectorXd& x) const = 0;

  /// Whether a slip phase's friction direction turns with the state (spatial ε(ζ_t)); its
  /// variational flow is then singular where a slip ends (TrajectorySensitivity grades there).
  virtual bool slip_direction_turns() const { return false; }

  /// Whether perturbations are reported in tangent coordinates other than the state's own
  /// (unit quaternions: 3 per orientation), with tangent_basis(x) (state perturbation of a
  /// tangent one) and tangent_projection(x) (its left inverse). Default: the state's own.
  virtual bool has_tangent_coordinates() const { return false; }
  virtual Eigen::MatrixXd tangent_basis(const Eigen::VectorXd& x) const {
    return Eigen::MatrixXd::Identity(x.size(), x.size());
  }
  virtual Eigen::MatrixXd tangent_projection(const Eigen::VectorXd& x) const {
    return Eigen::MatrixXd::Identity(x.size(), x.size());
  }
};

}  // namespace impactbench::sensitivity
