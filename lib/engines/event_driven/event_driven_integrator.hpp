#pragma once
// Event-driven hybrid integration of a Lagrangian system with unilateral contacts, Coulomb
// friction and impacts (source B.3).
//
// Each contact is open, slipping or sticking. Between events the state (q, v) follows the
// constrained flow of the current modes (constrained_flow.hpp), integrated by CVODE (BDF or
// Adams) or ARKODE's explicit Runge–Kutta pair (method = erk), error-controlled with dense
// output (flow_session.hpp). Guards, per contact, are root functions, each detected only when
// decreasing through zero:
//   open:  the gap h_n (impact when it closes with ζ_n < 0);
//   slip:  λ_n (lift-off) and ζ_t·s_ref (slip→stick; planar: the signed ζ_t σ. Spatial: the
//          projection on the slip direction at the segment start — it vanishes where ‖ζ_t‖ does
//          on a straight approach; a root with ‖ζ_t‖ > 0 only refreshes s_ref);
//   stick: λ_n (lift-off) and μ²λ_n² − ‖λ_t‖² (stick→slip, B.43 with μ).
// λ depends on the input u(t), so these guards do too. At a root the state is CVODE's dense
// output at the located time. Event processing, in order: impacts (impact_map.hpp: closed form
// with Γ for one contact, the impulse-level problem for several), Zeno detection (a contact
// whose predicted next impact interval or post-impact velocity after many impacts is tiny is
// made persistent: the impact is recomputed with e = 0 for it), then the acceleration-level
// complementarity problem over all closed and touching contacts (mode_consistency.hpp).
//
// The integrator holds a const reference to the system: the system must outlive it.
#include <functional>

#include <Eigen/Core>

#include "lib/engines/event_driven/event_driven_options.hpp"
#include "lib/engines/event_driven/event_types.hpp"
#include "lib/model/lagrangian_system.hpp"

namespace impactbench::engines::event_driven {

class EventDrivenIntegrator {
 public:
  /// u(t), size num_inputs(); may be empty when the system has no inputs (u = 0).
  using Input = std::function<Eigen::VectorXd(double)>;
  /// Called with every output sample, in time order; when given, the samples go to it instead of
  /// EventDrivenResult::samples (a long run streams them). They arrive in batches of up to 256
  /// (fewer for large systems), handed over between integration steps and at the end; the
  /// sample referred to is valid during the call only.
  using Observer = std::function<void(const SampleView&)>;

  /// Throws std::invalid_argument for an invalid option (non-positive tolerance, ...).
  explicit EventDrivenIntegrator(const model::LagrangianSystem<double>& system,
                                 EventDrivenOptions options = {});

  const EventDrivenOptions& options() const { return options_; }

  /// Integrates from t = 0 to `duration`. Throws std::invalid_argument for wrong sizes or
  /// non-finite initial data; every failure during the run is reported in the result's status.
  EventDrivenResult simulate(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                             const Input& input, double duration,
                             const Observer& observer = {}) const;

 private:
  const model::LagrangianSystem<double>& system_;
  EventDrivenOptions options_;
};

}  // namespace impactbench::engines::event_driven
