#include "lib/engines/event_driven/run_context.hpp"

#include <stdexcept>
#include <string>

#include "lib/output/message_text.hpp"

namespace impactbench::engines::event_driven {

std::shared_ptr<const MassFactor> RunContext::constant_mass_factor(
    const model::LagrangianSystem<double>& system) {
  if (!system.mass_matrix_is_constant()) return nullptr;
  // Any q will do: M does not depend on it.
  return std::make_shared<const MassFactor>(
      system.mass_matrix(Eigen::VectorXd::Zero(system.num_positions())));
}

std::shared_ptr<const MassFactor> RunContext::mass_factor(const Eigen::VectorXd& q) const {
  if (constant_mass_) return constant_mass_;
  return std::make_shared<const MassFactor>(system.mass_matrix(q));
}

Eigen::VectorXd RunContext::input_at(double t) const {
  if (system.num_inputs() == 0) return Eigen::VectorXd(0);
  if (!input) return Eigen::VectorXd::Zero(system.num_inputs());
  Eigen::VectorXd u = input(t);
  if (u.size() != system.num_inputs())
    throw std::invalid_argument("event-driven: input u(t) has size " + std::to_string(u.size()) +
                                ", the system has " + std::to_string(system.num_inputs()) +
                                " inputs");
  // A non-finite force cannot be integrated: stop instead of letting CVODE shrink its step.
  if (!u.allFinite())
    throw std::invalid_argument("event-driven: input u(t) is not finite at t = " +
                                output::number_text(t));
  return u;
}

Eigen::VectorXd RunContext::normalized_positions(const Eigen::VectorXd& q) const {
  // Unit quaternions drift under q̇ = N(q)v; integrate_position keeps them unit. The flow is
  // evaluated at the normalised q, so the drift of the norm never reaches the dynamics, and
  // the state is renormalised at every event.
  if (nq == nv) return q;
  return system.integrate_position(q, Eigen::VectorXd::Zero(nv), 0.0);
}

const model::Contact<double>* find_contact(const std::vector<model::Contact<double>>& contacts,
                                           const model::ContactKey& key) {
  return find_contact(contacts, key, contacts.size());  // no hint
}

const model::Contact<double>* find_contact(const std::vector<model::Contact<double>>& contacts,
                                           const model::ContactKey& key, std::size_t hint) {
  const std::ptrdiff_t i = index_of_key(contacts, key, hint);
  return i < 0 ? nullptr : &contacts[static_cast<std::size_t>(i)];
}

}  // namespace impactbench::engines::event_driven
