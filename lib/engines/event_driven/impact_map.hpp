#pragma once
// Jump maps at impacts (B.19–B.30), generalised to Newton restitution ζ_n⁺ = −e ζ_n⁻
// (e = 0 reproduces B.20/B.23).
//
// Single contact: the stick impulse Λ = −D⁻¹ (ζ⁻ + [e ζ_n⁻; 0]) with the Delassus matrix
// D = Jᵀ M⁻¹ J, J = [w_n W_t] (B.26–B.30), and Γ = μ² Λ_n² − ‖Λ_t‖² (B.25, with μ). Γ ≥ 0:
// the stick map (ζ_t⁺ = 0). Γ < 0: the slip map Λ_t = −μ Λ_n s (B.21), with Λ_n from the normal
// condition w_nᵀ M⁻¹ (w_n − μ W_t s) Λ_n = −(1 + e) ζ_n⁻. The text takes s = ε(ζ_t⁻); here
// s = −ε(Λ_t^stick), which differs when the impulse reverses the sliding (see impact_map.cpp).
// In space the slip branch solves the one-contact impulse-level Coulomb problem instead.
//
// Several contacts (simultaneous impacts, or an impact while other contacts are closed): the
// impulse-level friction-contact problem u = W Λ + q with W = Jᵀ M⁻¹ J over all of them and
// q = ζ⁻ + [e ζ_n⁻; 0] per contact, so that u_n = ζ_n⁺ + e ζ_n⁻ (Newton) and u_t = ζ_t⁺.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/constrained_flow.hpp"
#include "lib/engines/event_driven/event_driven_options.hpp"

namespace impactbench::engines::event_driven {

struct ContactImpulse {
  Eigen::VectorXd impulse;                ///< [Λ_n, Λ_t], size 1 + d
  Eigen::VectorXd zeta_before;            ///< [ζ_n⁻, ζ_t⁻]
  Eigen::VectorXd zeta_after;             ///< [ζ_n⁺, ζ_t⁺]
  ContactMode map = ContactMode::kStick;  ///< stick or slip map
  double gamma = 0.0;                     ///< Γ (B.25); NaN for simultaneous impacts
};

struct ImpactResult {
  Eigen::VectorXd v_plus;
  std::vector<ContactImpulse> contacts;
  bool ok = true;
  std::string message;
  /// The impulse-level LCP was solved by enumeration after the LCP solver failed
  /// (LocalContactSolution::enumerated).
  bool enumerated = false;
};

/// One contact, closed-form (B.25–B.30).
ImpactResult single_contact_impact(const DynamicsAtState& dynamics, const Eigen::VectorXd& v_minus,
                                   const model::Contact<double>& contact, double restitution,
                                   const EventDrivenOptions& options);

/// Several contacts, one impulse-level complementarity problem. `restitution[i]` overrides
/// the contact's e (Zeno handling sets it to 0).
ImpactResult simultaneous_impact(const DynamicsAtState& dynamics, const Eigen::VectorXd& v_minus,
                                 const std::vector<const model::Contact<double>*>& contacts,
                                 const std::vector<double>& restitution,
                                 const EventDrivenOptions& options);

}  // namespace impactbench::engines::event_driven
