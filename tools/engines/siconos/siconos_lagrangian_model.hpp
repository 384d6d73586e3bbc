#pragma once
// A general planar Lagrangian system in Siconos behind an Eigen/std-only interface (its source
// is compiled as C++17: see siconos_scheme.hpp): the mass, the forces and the contact
// kinematics come from callbacks, so that the system Siconos integrates is the
// project's own model (lib/model), not a re-statement of it.
//
// One LagrangianDS whose computeForces and force Jacobians call `forces`, one Interaction per
// contact with a NewtonImpactFrictionNSL and a LagrangianScleronomousR whose computeh and
// computeJachq call `kinematics` (row 0 the normal gap, row 1 the tangential direction), one
// MoreauJeanOSI, a FrictionContact of dimension 2 and a TimeStepping in fixed steps whose
// Newton loop solves the θ-method's implicit forces.
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "tools/engines/siconos/siconos_scheme.hpp"

namespace impactbench::adapters::siconos {

struct LagrangianForces {
  Eigen::VectorXd f;   ///< the generalised force F (M v̇ = F + contact forces)
  Eigen::MatrixXd dq;  ///< ∂F/∂q
  Eigen::MatrixXd dv;  ///< ∂F/∂v
};

struct ContactKinematics {
  double gap = 0.0;
  /// Row 0 w_nᵀ, rows 1.. W_tᵀ ((1 + d) × n, d = 1 planar, 2 spatial).
  Eigen::MatrixXd jacobian;
};

struct LagrangianProblem {
  Eigen::VectorXd q0;
  Eigen::VectorXd v0;
  Eigen::MatrixXd mass;  ///< constant
  std::function<LagrangianForces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v)>
      forces;
  int contacts = 0;
  std::function<ContactKinematics(int contact, const Eigen::VectorXd& q)> kinematics;
  std::vector<double> restitution;  ///< per contact
  std::vector<double> friction;     ///< per contact
};

struct NewtonLoop {
  double tolerance = 1e-10;  ///< Siconos' Newton criterion on the step's residual
  int max_iterations = 50;
};

class LagrangianModel {
 public:
  /// Throws std::runtime_error with Siconos' message when Siconos refuses.
  LagrangianModel(const LagrangianProblem& problem, const Scheme& scheme, const NewtonLoop& newton);
  ~LagrangianModel();
  LagrangianModel(const LagrangianModel&) = delete;
  LagrangianModel& operator=(const LagrangianModel&) = delete;

  /// One step of Siconos' TimeStepping (computeOneStep, nextStep).
  void step();
  Eigen::VectorXd q() const;
  Eigen::VectorXd v() const;
  /// The contact's impulse of the last step, (normal, tangents) [N·s].
  Eigen::VectorXd impulse(int contact) const;
  int iterations() const;  ///< the friction solver's, last solve
  double residual() const;
  /// Where the last step's contact problem took its contact Jacobians: Siconos' last Newton
  /// iterate of q_k+1 before the final state (q_k + h v_k after one iteration).
  Eigen::VectorXd law_frame_point() const;
  int newton_iterations() const;  ///< of the last step
  bool newton_converged() const;

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

}  // namespace impactbench::adapters::siconos
