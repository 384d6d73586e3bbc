#include "tools/adapters/siconos/siconos_planar_model.hpp"

#include <siconos/numerics/SolverOptions.h>
#include <siconos/kernel/FrictionContact.hpp>
#include <siconos/kernel/Interaction.hpp>
#include <siconos/kernel/LagrangianLinearTIDS.hpp>
#include <siconos/kernel/LagrangianLinearTIR.hpp>
#include <siconos/kernel/MoreauJeanOSI.hpp>
#include <siconos/kernel/NewtonImpactFrictionNSL.hpp>
#include <siconos/kernel/NonSmoothDynamicalSystem.hpp>
#include <siconos/kernel/SiconosVector.hpp>
#include <siconos/kernel/SimpleMatrix.hpp>
#include <siconos/kernel/TimeDiscretisation.hpp>
#include <siconos/kernel/TimeStepping.hpp>

#include <stdexcept>

#include "tools/adapters/siconos/siconos_guard.hpp"

namespace impactbench::adapters::siconos {
namespace {

int fc2d_solver_id(Fc2dSolver solver) {
  switch (solver) {
    case Fc2dSolver::kNsgs:
      return SICONOS_FRICTION_2D_NSGS;
    case Fc2dSolver::kLemke:
      return SICONOS_FRICTION_2D_LEMKE;
    case Fc2dSolver::kEnum:
      return SICONOS_FRICTION_2D_ENUM;
    case Fc2dSolver::kCpg:
      return SICONOS_FRICTION_2D_CPG;
  }
  throw std::logic_error("unknown fc2d solver");
}

}  // namespace

struct PlanarModel::Parts {
  std::vector<SP::LagrangianLinearTIDS> bodies;
  std::vector<SP::SiconosVector> forces;  // the bodies' fExt, changed in place
  std::vector<SP::Interaction> interactions;
  SP::FrictionContact problem;
  SP::TimeStepping simulation;
  std::vector<Eigen::Vector2d> impulses;  // of the last step, per interaction
};

PlanarModel::PlanarModel(const std::vector<PlanarBody>& bodies,
                         const std::vector<PlanarContact>& contacts, const Scheme& scheme)
    : parts_(std::make_unique<Parts>()) {
  guarded([&] {
    auto nsds = std::make_shared<NonSmoothDynamicalSystem>(0.0, scheme.duration);
    for (const PlanarBody& body : bodies) {
      parts_->forces.push_back(siconos_vector(body.force));
      auto ds = planar_ds(body, parts_->forces.back());
      nsds->insertDynamicalSystem(ds);
      parts_->bodies.push_back(ds);
    }
    for (const PlanarContact& c : contacts) {
      auto h = std::make_shared<SimpleMatrix>(2, 3);
      for (unsigned row = 0; row < 2; ++row)
        for (unsigned col = 0; col < 3; ++col) (*h)(row, col) = c.h(row, col);
      auto relation = std::make_shared<LagrangianLinearTIR>(h, siconos_vector(c.b));
      auto law = std::make_shared<NewtonImpactFrictionNSL>(c.restitution, 0.0, c.friction, 2);
      auto interaction = std::make_shared<Interaction>(law, relation);
      nsds->link(interaction, parts_->bodies.at(static_cast<std::size_t>(c.body)));
      parts_->interactions.push_back(interaction);
    }
    auto osi = std::make_shared<MoreauJeanOSI>(scheme.theta, scheme.gamma);
    osi->setConstraintActivationThreshold(scheme.activation_threshold);
    parts_->problem = std::make_shared<FrictionContact>(2, fc2d_solver_id(scheme.solver));
    parts_->problem->numericsSolverOptions()->iparam[SICONOS_IPARAM_MAX_ITER] =
        scheme.max_iterations;
    parts_->problem->numericsSolverOptions()->dparam[SICONOS_DPARAM_TOL] = scheme.tolerance;
    parts_->simulation = std::make_shared<TimeStepping>(
        nsds, std::make_shared<TimeDiscretisation>(0.0, scheme.dt), osi, parts_->problem);
    return 0;
  });
}

PlanarModel::~PlanarModel() = default;

void PlanarModel::set_force(int body, const Eigen::Vector3d& force) {
  SiconosVector& f = *parts_->forces.at(static_cast<std::size_t>(body));
  for (unsigned i = 0; i < 3; ++i) f(i) = force[i];
}

void PlanarModel::step() {
  guarded([&] {
    parts_->simulation->computeOneStep();
    // Read before nextStep, which resets the interactions' multipliers for the next step.
    parts_->impulses.clear();
    for (const SP::Interaction& interaction : parts_->interactions) {
      const SiconosVector& p = *interaction->lambda(1);
      parts_->impulses.emplace_back(p(0), p(1));
    }
    parts_->simulation->nextStep();
    return 0;
  });
}

Eigen::Vector3d PlanarModel::q(int body) const {
  return eigen3(*parts_->bodies.at(static_cast<std::size_t>(body))->q());
}

Eigen::Vector3d PlanarModel::v(int body) const {
  return eigen3(*parts_->bodies.at(static_cast<std::size_t>(body))->velocity());
}

Eigen::Vector2d PlanarModel::impulse(int contact) const {
  if (parts_->impulses.empty()) return Eigen::Vector2d::Zero();  // no step yet
  return parts_->impulses.at(static_cast<std::size_t>(contact));
}

int PlanarModel::iterations() const {
  return parts_->problem->numericsSolverOptions()->iparam[SICONOS_IPARAM_ITER_DONE];
}

double PlanarModel::residual() const {
  return parts_->problem->numericsSolverOptions()->dparam[SICONOS_DPARAM_RESIDU];
}

}  // namespace impactbench::adapters::siconos
