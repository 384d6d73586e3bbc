#include "tools/engines/siconos/siconos_event_driven_model.hpp"

#include <siconos/kernel/Event.hpp>
#include <siconos/kernel/EventDriven.hpp>
#include <siconos/kernel/EventsManager.hpp>
#include <siconos/kernel/Interaction.hpp>
#include <siconos/kernel/LCP.hpp>
#include <siconos/kernel/LagrangianLinearTIDS.hpp>
#include <siconos/kernel/LagrangianLinearTIR.hpp>
#include <siconos/kernel/LsodarOSI.hpp>
#include <siconos/kernel/NewtonImpactNSL.hpp>
#include <siconos/kernel/NonSmoothDynamicalSystem.hpp>
#include <siconos/kernel/SiconosVector.hpp>
#include <siconos/kernel/SimpleMatrix.hpp>
#include <siconos/kernel/SimulationGraphs.hpp>
#include <siconos/kernel/TimeDiscretisation.hpp>

#include <stdexcept>
#include <string>

#include "tools/engines/siconos/siconos_guard.hpp"

namespace impactbench::adapters::siconos {

struct EventDrivenModel::Parts {
  std::vector<SP::LagrangianLinearTIDS> bodies;
  std::vector<NormalContact> contacts;
  std::vector<SP::Interaction> interactions;
  SP::EventDriven simulation;
  // Lsodar's steps: LsodarOSI::count_NST is the step count of the current problem, which
  // Siconos restarts at nonsmooth events; summed here over its increases and restarts.
  long steps = 0;
  long last_count = 0;
  std::vector<double> impulses;    // of the last nonsmooth event, per interaction
  std::vector<double> approaches;  // normal velocity before it
  double normal_velocity(std::size_t contact) const {
    const NormalContact& c = contacts[contact];
    const SiconosVector& v = *bodies[static_cast<std::size_t>(c.body)]->velocity();
    return c.h(0) * v(0) + c.h(1) * v(1) + c.h(2) * v(2);
  }
};

EventDrivenModel::EventDrivenModel(const std::vector<PlanarBody>& bodies,
                                   const std::vector<NormalContact>& contacts,
                                   const EventDrivenScheme& scheme)
    : parts_(std::make_unique<Parts>()) {
  parts_->contacts = contacts;
  parts_->impulses.assign(contacts.size(), 0.0);
  parts_->approaches.assign(contacts.size(), 0.0);
  parts_->last_count = LsodarOSI::count_NST;
  guarded([&] {
    auto nsds = std::make_shared<NonSmoothDynamicalSystem>(0.0, scheme.duration);
    for (const PlanarBody& body : bodies) {
      auto ds = planar_ds(body, siconos_vector(body.force));
      nsds->insertDynamicalSystem(ds);
      parts_->bodies.push_back(ds);
    }
    for (const NormalContact& c : contacts) {
      auto h = std::make_shared<SimpleMatrix>(1, 3);
      for (unsigned col = 0; col < 3; ++col) (*h)(0, col) = c.h(col);
      auto b = std::make_shared<SiconosVector>(1);
      (*b)(0) = c.b;
      auto relation = std::make_shared<LagrangianLinearTIR>(h, b);
      auto law = std::make_shared<NewtonImpactNSL>(c.restitution);
      auto interaction = std::make_shared<Interaction>(law, relation);
      nsds->link(interaction, parts_->bodies.at(static_cast<std::size_t>(c.body)));
      parts_->interactions.push_back(interaction);
    }
    auto osi = std::make_shared<LsodarOSI>();
    // Scalar tolerances (itol = 1) through the array overload: Siconos 4.4's scalar overload
    // stores rtol in place of atol.
    boost::shared_array<double> rtol(new double[1]{scheme.rtol});
    boost::shared_array<double> atol(new double[1]{scheme.atol});
    osi->setTol(1, rtol, atol);
    parts_->simulation = std::make_shared<EventDriven>(
        nsds, std::make_shared<TimeDiscretisation>(0.0, scheme.sample_dt));
    parts_->simulation->insertIntegrator(osi);
    parts_->simulation->setToleranceED(scheme.event_tolerance);  // static: set on every run
    // Impact LCP (Newton's law at the impulse level) and acceleration LCP (persistent
    // contacts), both Lemke, Siconos' default.
    parts_->simulation->insertNonSmoothProblem(std::make_shared<LCP>(), SICONOS_OSNSP_ED_IMPACT);
    parts_->simulation->insertNonSmoothProblem(std::make_shared<LCP>(),
                                               SICONOS_OSNSP_ED_SMOOTH_ACC);
    parts_->simulation->initialize();
    return 0;
  });
}

EventDrivenModel::~EventDrivenModel() = default;

bool EventDrivenModel::has_next_event() const {
  return parts_->simulation->hasNextEvent();
}

ProcessedEvent EventDrivenModel::advance() {
  return guarded([&] {
    EventDriven& simulation = *parts_->simulation;
    simulation.advanceToEvent();
    const long count = LsodarOSI::count_NST;
    parts_->steps += count >= parts_->last_count ? count - parts_->last_count : count;
    parts_->last_count = count;
    const Event& next = *simulation.eventsManager()->nextEvent();
    ProcessedEvent event{next.getDoubleTimeOfEvent(), next.getType() == NS_EVENT};
    if (event.nonsmooth)
      for (std::size_t i = 0; i < parts_->contacts.size(); ++i)
        parts_->approaches[i] = parts_->normal_velocity(i);
    simulation.processEvents();
    if (event.nonsmooth)
      for (std::size_t i = 0; i < parts_->contacts.size(); ++i) {
        // The impact LCP sets λ of the contacts it solved for; a contact whose normal
        // velocity did not jump took no impulse (its λ is a leftover of an earlier solve).
        const bool jumped = parts_->normal_velocity(i) > parts_->approaches[i];
        parts_->impulses[i] = jumped ? (*parts_->interactions[i]->lambda(1))(0) : 0.0;
      }
    return event;
  });
}

Eigen::Vector3d EventDrivenModel::q(int body) const {
  return eigen3(*parts_->bodies.at(static_cast<std::size_t>(body))->q());
}

Eigen::Vector3d EventDrivenModel::v(int body) const {
  return eigen3(*parts_->bodies.at(static_cast<std::size_t>(body))->velocity());
}

double EventDrivenModel::impulse(int contact) const {
  return parts_->impulses.at(static_cast<std::size_t>(contact));
}

double EventDrivenModel::approach_velocity(int contact) const {
  return parts_->approaches.at(static_cast<std::size_t>(contact));
}

bool EventDrivenModel::persistent(int contact) const {
  const SP::InteractionsGraph index_set = parts_->simulation->indexSet(2);
  return index_set &&
         index_set->is_vertex(parts_->interactions.at(static_cast<std::size_t>(contact)));
}

long EventDrivenModel::integrator_steps() const {
  return parts_->steps;
}

}  // namespace impactbench::adapters::siconos
