#pragma once
// Siconos' event-driven scheme behind an Eigen/std-only interface (its source is compiled as
// C++17: see siconos_scheme.hpp).
//
// Planar bodies as LagrangianLinearTIDS in q = (x, y, θ) with a constant external force, each
// contact an Interaction with a NewtonImpactNSL and a LagrangianLinearTIR of one row, the
// normal gap y = h q + b; a LsodarOSI integrates the smooth motion and locates the zeros of the
// gaps, an EventDriven simulation processes the events: at a nonsmooth event an impact LCP
// (Newton's law on the closing contacts), on persistent contacts an acceleration LCP.
// Frictionless only: Siconos 4.4's EventDriven states unilateral contacts without friction.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "tools/engines/siconos/siconos_scheme.hpp"

namespace impactbench::adapters::siconos {

struct NormalContact {
  int body = 0;
  Eigen::RowVector3d h = Eigen::RowVector3d::Zero();  ///< gap = h q + b
  double b = 0.0;
  double restitution = 0.0;
};

struct EventDrivenScheme {
  double sample_dt = 1e-3;  ///< the time discretisation: an event every sample_dt
  double duration = 1.0;    ///< the simulation's end (the last sample time)
  double rtol = 1e-12;      ///< Lsodar's relative tolerance (scalar, on every state component)
  double atol = 1e-14;      ///< Lsodar's absolute tolerance
  double event_tolerance = 2.220446049250313e-12;  ///< Siconos' _TOL_ED [m] (static in Siconos)
};

/// One processed event.
struct ProcessedEvent {
  double t = 0.0;
  bool nonsmooth = false;  ///< an impact or contact change (Siconos' NS_EVENT), else a sample
};

class EventDrivenModel {
 public:
  /// Throws std::runtime_error with Siconos' message (first line) when Siconos refuses.
  EventDrivenModel(const std::vector<PlanarBody>& bodies,
                   const std::vector<NormalContact>& contacts, const EventDrivenScheme& scheme);
  ~EventDrivenModel();
  EventDrivenModel(const EventDrivenModel&) = delete;
  EventDrivenModel& operator=(const EventDrivenModel&) = delete;

  bool has_next_event() const;
  /// Integrates to the next event (advanceToEvent) and processes it (processEvents).
  ProcessedEvent advance();
  Eigen::Vector3d q(int body) const;
  Eigen::Vector3d v(int body) const;
  /// The contact's normal impulse at the last nonsmooth event [N·s] (0 if it did not impact).
  double impulse(int contact) const;
  /// The contact's pre-event normal velocity at the last nonsmooth event [m/s].
  double approach_velocity(int contact) const;
  /// Whether the contact is in Siconos' index set 2 (closed and persistent) after the event.
  bool persistent(int contact) const;
  /// Lsodar's steps since this model was built.
  long integrator_steps() const;

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

}  // namespace impactbench::adapters::siconos
