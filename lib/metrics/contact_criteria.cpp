#include "lib/metrics/contact_criteria.hpp"

#include <algorithm>
#include <cmath>

namespace impactbench::metrics {

double restituted_normal_velocity(const engines::ContactSample& c) {
  return c.velocity_n + c.restitution * std::min(c.velocity_n_before, 0.0);
}

ContactCriteria contact_criteria(const engines::ContactSample& c, double slip_velocity) {
  ContactCriteria k;
  const double slip = c.velocity_t.norm();
  const double zeta_n = restituted_normal_velocity(c);
  k.signorini = std::abs(c.impulse_n * zeta_n);
  k.friction_cone = std::max(0.0, c.impulse_t.norm() - c.friction * c.impulse_n);
  if (slip > slip_velocity)
    k.max_dissipation = (c.impulse_t + c.friction * c.impulse_n * c.velocity_t / slip).norm();
  k.complementarity =
      std::abs(c.impulse_n * (zeta_n + c.friction * slip) + c.impulse_t.dot(c.velocity_t));
  k.penetration = std::max(0.0, -c.gap);
  return k;
}

ContactCriteria worst_contact_criteria(const std::vector<engines::StepRecord>& steps,
                                       double slip_velocity) {
  ContactCriteria worst;
  for (const auto& step : steps)
    for (const auto& contact : step.contacts) {
      const ContactCriteria k = contact_criteria(contact, slip_velocity);
      worst.signorini = std::max(worst.signorini, k.signorini);
      worst.friction_cone = std::max(worst.friction_cone, k.friction_cone);
      worst.max_dissipation = std::max(worst.max_dissipation, k.max_dissipation);
      worst.complementarity = std::max(worst.complementarity, k.complementarity);
      worst.penetration = std::max(worst.penetration, k.penetration);
    }
  return worst;
}

}  // namespace impactbench::metrics
