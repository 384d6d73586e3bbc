#pragma once
// The nominal trajectory of the sensitivity module from a run of the event-driven integrator
// (lib/engines/event_driven).
//
// Mapping. Contacts are indexed in the order of the system's find_contacts. The initial mode is
// the run's first event state (the integrator's mode consistency at t = 0). At every later event
// instant:
//   - instants with impacts: one micro event per impacting contact, with the phase the contact
//     holds after the instant; another closed contact whose phase the impulse changes (a
//     sliding corner reversing when the other corner lands, a rocking block's old pivot
//     lifting off) is carried by the impact's reset (MicroEvent::carried, single impacts
//     only), not treated as a guard crossing;
//   - other instants: one micro event per logged mode change (lift-off, slip→stick, stick→slip,
//     slip reversal = slip→stick guard into the opposite slip);
//   - touchdowns (grazing, ζ_n = 0) and Zeno rests have no first-order jump gain: rejected.
// Planar slip directions: the sign of ζ_t after the instant, or, when ζ_t = 0 (stick→slip), the
// direction opposite to the stick friction force just before. Closed frictionless contacts are
// slip phases. The post-event states of the run restart the module's segments.
#include "lib/engines/event_driven/event_types.hpp"
#include "lib/model/lagrangian_system.hpp"
#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/nominal_trajectory.hpp"

namespace impactbench::sensitivity {

/// Throws std::invalid_argument naming the event that cannot be linearised, or a run that did
/// not succeed.
NominalTrajectory nominal_from_event_run(const MechanicalHybridModel& model,
                                         const model::LagrangianSystem<double>& system,
                                         const engines::event_driven::EventDrivenResult& run,
                                         const InputFunction& input,
                                         const InputFunction& input_rate, double duration);

}  // namespace impactbench::sensitivity
