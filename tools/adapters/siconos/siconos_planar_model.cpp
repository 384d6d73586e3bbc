#include "tools/adapters/siconos/siconos_planar_model.hpp"

#include <siconos/kernel/Interaction.hpp>
#include <siconos/kernel/LagrangianLinearTIDS.hpp>
#include <siconos/kernel/LagrangianLinearTIR.hpp>
#include <siconos/kernel/NewtonImpactFrictionNSL.hpp>
#include <siconos/kernel/NonSmoothDynamicalSystem.hpp>
#include <siconos/kernel/SiconosVector.hpp>
#include <siconos/kernel/SimpleMatrix.hpp>

#include "tools/adapters/siconos/siconos_guard.hpp"
#include "tools/adapters/siconos/siconos_moreau_jean_stepping.hpp"

namespace impactbench::adapters::siconos {
struct PlanarModel::Parts {
  std::vector<SP::LagrangianLinearTIDS> bodies;
  std::vector<SP::SiconosVector> forces;  // the bodies' fExt, changed in place
  std::unique_ptr<MoreauJeanStepping> stepping;
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
    std::vector<SP::Interaction> interactions;
    for (const PlanarContact& c : contacts) {
      auto h = std::make_shared<SimpleMatrix>(2, 3);
      for (unsigned row = 0; row < 2; ++row)
        for (unsigned col = 0; col < 3; ++col) (*h)(row, col) = c.h(row, col);
      auto relation = std::make_shared<LagrangianLinearTIR>(h, siconos_vector(c.b));
      auto law = std::make_shared<NewtonImpactFrictionNSL>(c.restitution, 0.0, c.friction, 2);
      auto interaction = std::make_shared<Interaction>(law, relation);
      nsds->link(interaction, parts_->bodies.at(static_cast<std::size_t>(c.body)));
      interactions.push_back(interaction);
    }
    parts_->stepping = std::make_unique<MoreauJeanStepping>(nsds, interactions, scheme);
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
    parts_->stepping->step();
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
  return parts_->stepping->impulse(contact);
}

int PlanarModel::iterations() const {
  return parts_->stepping->iterations();
}

double PlanarModel::residual() const {
  return parts_->stepping->residual();
}

}  // namespace impactbench::adapters::siconos
