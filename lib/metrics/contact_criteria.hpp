#pragma once
// Per-step physical-accuracy criteria of Le Lidec et al. (2024, "Contact models in robotics: a
// comparative analysis"), computed from the impulses and post-step relative velocities each
// engine reports. All are zero for an exact solution of the velocity-level Coulomb–Signorini
// law with Newton's restitution, written on ζ_n = ζ_n⁺ + e min(ζ_n⁻, 0) (ζ_n⁻, ζ_n⁺: normal
// relative velocity before and after the step, the law Moreau–Jean solves): an exact impact
// at any e scores 0, where λ_n ζ_n⁺ alone would count the rebound as a violation.
#include <vector>

#include "lib/engines/run_result.hpp"

namespace impactbench::metrics {

struct ContactCriteria {
  double signorini = 0.0;        ///< |λ_n ζ_n|: impulse while separating [N·m]
  double friction_cone = 0.0;    ///< max(0, ‖λ_t‖ − μ λ_n) [N·s]
  double max_dissipation = 0.0;  ///< ‖λ_t + μ λ_n ζ_t/‖ζ_t‖‖ when sliding [N·s]
  double complementarity = 0.0;  ///< |λ_n (ζ_n + μ‖ζ_t‖) + λ_tᵀ ζ_t| (De Saxcé) [N·m]
  double penetration = 0.0;      ///< max(0, −gap) [m]
};

/// ζ_n = ζ_n⁺ + e min(ζ_n⁻, 0), the normal velocity of the law with restitution [m/s].
double restituted_normal_velocity(const engines::ContactSample& contact);

/// The criteria of one contact sample. A contact slides when ‖ζ_t‖ > slip_velocity [m/s].
ContactCriteria contact_criteria(const engines::ContactSample& contact, double slip_velocity);

/// Worst (∞-norm) of each criterion over every contact of every step.
ContactCriteria worst_contact_criteria(const std::vector<engines::StepRecord>& steps,
                                       double slip_velocity = 1e-6);

}  // namespace impactbench::metrics
