#pragma once
// First-order sensitivity of a hybrid trajectory (source C and D): along the nominal α(t), μ(t)
//     ż = A(t) z + B(t) v(t)             in each mode (C.5, D.13–D.15),
//     z⁺ = H(z⁻, v(τ))                  at each macro event (C.39, C.60, D.9),
// so that a perturbed trajectory with x(t_begin) = α(t_begin) + ε z0 and input μ + ε v is
// x_ε(t) = α(t) + ε z(t) + O(ε²) at every t away from the event times (between a nominal and a
// perturbed event time, the comparison is with the mode's trajectory extended past the event).
//
// Numerics. Each segment between events is integrated with classical RK4 on a uniform grid of
// at most `max_step`; the nominal and the model's Jacobians A, B at every RK4 stage are stored
// once (forward-mode AD), so each z(t) for a new (z0, v) costs only matrix–vector products. The
// z-RK4 uses the same stages as the nominal's, i.e. it is exactly the RK4 step of the augmented
// system (α, z). Values between grid points are cubic Hermite interpolants (error O(h⁴)).
#include <vector>

#include <Eigen/Core>

#include "lib/sensitivity/conewise_jump_gain.hpp"
#include "lib/sensitivity/hybrid_model.hpp"
#include "lib/sensitivity/nominal_trajectory.hpp"

namespace impactbench::sensitivity {

struct SensitivityOptions {
  double max_step = 1e-3;  ///< RK4 step bound [s], > 0
};

/// One mode's piece of the nominal with its linearisation at the RK4 stages.
struct LinearisedSegment {
  HybridMode mode;
  double t_begin = 0.0, t_end = 0.0, h = 0.0;
  int steps = 0;
  /// Graded grid (steps + 1 times; empty: uniform, t_begin + k h). A spatial slip ending at
  /// ‖ζ_t‖ = 0 has a variational flow singular there: the turn of ε(ζ_t) = ζ_t/‖ζ_t‖ enters as
  /// (I − ε εᵀ)/‖ζ_t‖ while the perpendicular perturbation of ζ_t vanishes like ‖ζ_t‖. Its last
  /// steps are replaced by steps of a fixed small fraction of the time left before the event
  /// (trajectory_sensitivity.cpp), so that h‖A‖ stays small and RK4 accurate; the grid stops
  /// 2⁻²⁴ of a step short of the event (a state change of that order, far below the ε² the
  /// module is checked to).
  ///
  /// A spatial slip starting at ‖ζ_t‖ = 0 (after stick → slip) has the same term with ‖ζ_t‖
  /// growing like (t − t*)²: a decay rate without bound at the start, which a graded grid does
  /// not tame. Its first steps are L-stable Rosenbrock steps growing with the time since the
  /// onset, then RK4 steps with h ≤ 1/‖A‖∞ (trajectory_sensitivity.cpp); the slip direction's
  /// smoothing below the velocity tolerance (lib/model/slip_direction.hpp) bounds ‖A‖ at the
  /// onset.
  std::vector<double> times;
  /// Per step: 1 for a Rosenbrock step (A, B of its start in slot 4k, of its end stage in
  /// 4k + 1), 0 for RK4; empty: all RK4.
  std::vector<char> rosenbrock;
  std::vector<Eigen::VectorXd> alpha;       ///< α at the steps + 1 grid points
  std::vector<Eigen::VectorXd> alpha_rate;  ///< f at the grid points
  /// A, B at the stages: 4 per step (stage s of step k at 4k + s), then the end grid point.
  std::vector<Eigen::MatrixXd> A, B;
};

/// z(T) = state z0 + input p for the input perturbation v(t) = V(t) p (V: m × p basis).
struct EndPointSensitivity {
  Eigen::MatrixXd state;                 ///< Φ(T, t_begin) through all gains, n × n
  Eigen::MatrixXd input;                 ///< n × p
  std::vector<std::vector<int>> orders;  ///< micro-event order used at each macro event
};

/// Input-perturbation basis V(t), m × p.
using InputBasis = std::function<Eigen::MatrixXd(double t)>;

class TrajectorySensitivity {
 public:
  /// Integrates the nominal and linearises it. The model must outlive this object. Throws
  /// std::invalid_argument for an invalid nominal or options, std::runtime_error when an event's
  /// guard is not crossed transversally at the integrated pre-event state.
  TrajectorySensitivity(const HybridModel& model, NominalTrajectory nominal,
                        SensitivityOptions options = {});

  const HybridModel& model() const { return model_; }
  const NominalTrajectory& nominal() const { return nominal_; }
  const std::vector<LinearisedSegment>& segments() const { return segments_; }
  /// One conewise gain per nominal event (segments()[k] ends at events()[k]).
  const std::vector<ConewiseJumpGain>& events() const { return events_; }

  /// α(t) (pre-event value at an event time).
  Eigen::VectorXd nominal_state(double t) const;
  /// z(t) at the given non-decreasing times in [t_begin, t_end] (pre-event value at an event
  /// time), for z(t_begin) = z0 and input perturbation v (empty: zero).
  std::vector<Eigen::VectorXd> perturbation(const Eigen::VectorXd& z0, const InputFunction& v,
                                            const std::vector<double>& times) const;
  /// The end-point sensitivity with the gains of the cone of the direction (cone_z0, cone_p)
  /// (zero: the listed order of each macro event).
  EndPointSensitivity end_point_sensitivity(const InputBasis& basis,
                                            const Eigen::VectorXd& cone_z0 = {},
                                            const Eigen::VectorXd& cone_p = {}) const;

 private:
  LinearisedSegment linearise_segment(const HybridMode& mode, double t0, double t1,
                                      const Eigen::VectorXd& x0, bool graded_end = false,
                                      bool stiff_start = false) const;
  LinearisedSegment linearise_stiff_start(LinearisedSegment seg, const Eigen::VectorXd& x0,
                                          bool graded_end) const;
  Eigen::VectorXd input_perturbation(const InputFunction& v, double t) const;

  const HybridModel& model_;
  NominalTrajectory nominal_;
  SensitivityOptions options_;
  std::vector<LinearisedSegment> segments_;
  std::vector<ConewiseJumpGain> events_;
};

}  // namespace impactbench::sensitivity
