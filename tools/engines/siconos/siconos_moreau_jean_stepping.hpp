#pragma once
// Siconos' Moreau–Jean time-stepping on a built NonSmoothDynamicalSystem: a MoreauJeanOSI with
// θ, γ and the activation threshold, a FrictionContact of dimension 2 solved by an fc2d solver
// and a TimeStepping in fixed steps; each step's impulses read before Siconos resets them.
// Include it only from the files that include Siconos (compiled as C++17, see
// siconos_scheme.hpp).
#include <siconos/numerics/SolverOptions.h>
#include <siconos/kernel/FrictionContact.hpp>
#include <siconos/kernel/Interaction.hpp>
#include <siconos/kernel/MoreauJeanOSI.hpp>
#include <siconos/kernel/NonSmoothDynamicalSystem.hpp>
#include <siconos/kernel/SiconosVector.hpp>
#include <siconos/kernel/TimeDiscretisation.hpp>
#include <siconos/kernel/TimeStepping.hpp>

#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "tools/engines/siconos/siconos_guard.hpp"
#include "tools/engines/siconos/siconos_scheme.hpp"

namespace impactbench::adapters::siconos {

class MoreauJeanStepping {
 public:
  /// `interactions` are the nsds's, in the order impulse() numbers them.
  MoreauJeanStepping(const SP::NonSmoothDynamicalSystem& nsds,
                     std::vector<SP::Interaction> interactions, const Scheme& scheme)
      : interactions_(std::move(interactions)) {
    auto osi = std::make_shared<MoreauJeanOSI>(scheme.theta, scheme.gamma);
    osi->setConstraintActivationThreshold(scheme.activation_threshold);
    problem_ = std::make_shared<FrictionContact>(
        scheme.contact_dimension, friction_solver_id(scheme.solver, scheme.contact_dimension));
    problem_->numericsSolverOptions()->iparam[SICONOS_IPARAM_MAX_ITER] = scheme.max_iterations;
    problem_->numericsSolverOptions()->dparam[SICONOS_DPARAM_TOL] = scheme.tolerance;
    simulation_ = std::make_shared<TimeStepping>(
        nsds, std::make_shared<TimeDiscretisation>(0.0, scheme.dt), osi, problem_);
  }

  TimeStepping& simulation() { return *simulation_; }
  const TimeStepping& simulation() const { return *simulation_; }

  /// computeOneStep, the impulses, nextStep (which resets the interactions' multipliers).
  void step() {
    simulation_->computeOneStep();
    impulses_.clear();
    for (const SP::Interaction& interaction : interactions_) {
      const SiconosVector& p = *interaction->lambda(1);
      Eigen::VectorXd impulse(p.size());
      for (unsigned i = 0; i < p.size(); ++i) impulse[i] = p(i);
      impulses_.push_back(impulse);
    }
    simulation_->nextStep();
  }

  /// The contact's impulse of the last step, (normal, tangents) [N·s].
  Eigen::VectorXd impulse(int contact) const {
    if (impulses_.empty()) return Eigen::VectorXd::Zero(2);  // no step yet
    return impulses_.at(static_cast<std::size_t>(contact));
  }
  int iterations() const {
    return problem_->numericsSolverOptions()->iparam[SICONOS_IPARAM_ITER_DONE];
  }
  double residual() const {
    return problem_->numericsSolverOptions()->dparam[SICONOS_DPARAM_RESIDU];
  }

 private:
  std::vector<SP::Interaction> interactions_;
  SP::FrictionContact problem_;
  SP::TimeStepping simulation_;
  std::vector<Eigen::VectorXd> impulses_;
};

}  // namespace impactbench::adapters::siconos
