#pragma once
// The impacts of one event instant, in four steps: the participants (every contact closed at
// the instant), the impulse solve, the Zeno decision for each contact that bounces off, and the
// commit of the new modes and events.
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/contact_modes.hpp"
#include "lib/engines/event_driven/impact_map.hpp"
#include "lib/engines/event_driven/run_context.hpp"
#include "lib/engines/event_driven/zeno_rule.hpp"

namespace impactbench::engines::event_driven {

/// Moreau's impact law acts on every contact closed at the instant: the closing ones, the
/// closed ones and the open ones that merely touch (a row of touching balls struck at one end
/// takes the blow together, not pair by pair). A touching contact enters with e min(ζ_n⁻, 0)
/// = 0 (impact_map.cpp) and keeps its mode: the mode decision after the impacts settles it.
struct ImpactParticipants {
  std::vector<const model::Contact<double>*> contacts;
  std::vector<bool> impacting;  ///< open at the surface and closing faster than velocity_tolerance
  std::vector<bool> touching;   ///< open at the surface, not closing
  std::vector<double> restitution;  ///< e per contact (0 for those the Zeno rule rests)
  bool any_impacting() const;
};

ImpactParticipants impact_participants(const std::vector<model::Contact<double>>& contacts,
                                       const ContactModes& modes, const Eigen::VectorXd& v,
                                       const EventDrivenOptions& options);

ImpactResult solve_impact(const DynamicsAtState& dynamics, const Eigen::VectorXd& v,
                          const ImpactParticipants& participants,
                          const EventDrivenOptions& options);

/// The Zeno rule for each participant that bounces off (the others: no rest); sets the
/// restitution of the contacts that rest to 0.
std::vector<ZenoDecision> zeno_decisions(const RunContext& run, const ContactModes& modes, double t,
                                         const Eigen::VectorXd& q, const ImpactResult& impact,
                                         ImpactParticipants& participants);

/// Applies the impacts at (t, q) to v, updates the modes and logs the events (not the mode
/// changes of an initial instant without impact). False, with the failure recorded, when a
/// contact problem has no solution.
bool apply_impacts(const RunContext& run, double t, const Eigen::VectorXd& q, Eigen::VectorXd& v,
                   const std::vector<model::Contact<double>>& contacts, bool initial,
                   ContactModes& modes, EventDrivenResult& result);

}  // namespace impactbench::engines::event_driven
