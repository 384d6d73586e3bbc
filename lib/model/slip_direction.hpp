#pragma once
// The slip direction ε(ζ_t) of a spatial Coulomb contact, one definition for the event-driven
// engine (double) and the sensitivity model (automatic differentiation), so that the model
// linearises the flow the engine integrates.
//
// Coulomb's ζ_t/‖ζ_t‖, oriented along the reference s_ref (continuous through ζ_t = 0 on a
// straight path, so a flow extends past its slip→stick root). Below `blend_speed` (the engine's
// velocity_tolerance, the speed that counts as sticking) it is the unit vector of
// ζ_t + blend_speed (1 − x²)² s_ref, x = ‖ζ_t‖/blend_speed: s_ref at ζ_t = 0 and C¹ in ζ_t.
// Coulomb's direction turns the force at a rate μλ_n‖W_t‖/‖ζ_t‖; after a stick→slip onset, where
// ζ_t grows from zero like (t − t*)², that rate has no bound, and a switch from s_ref to
// ζ_t/‖ζ_t‖ at one speed is a jump in the force that no step size resolves.
#include <cmath>

#include <Eigen/Core>

namespace impactbench::model {

template <typename Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, 1> smoothed_slip_direction(
    const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& zeta_t,
    const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& reference, double blend_speed) {
  using std::sqrt;
  const Scalar squared = zeta_t.squaredNorm();
  const double sign = zeta_t.dot(reference) < 0.0 ? -1.0 : 1.0;
  if (squared >= blend_speed * blend_speed) {
    const Scalar norm = sqrt(squared);
    return sign * zeta_t / norm;
  }
  // The weight is written in ‖ζ_t‖², which is smooth at ζ_t = 0 (‖ζ_t‖ is not).
  const Scalar x2 = squared / (blend_speed * blend_speed);
  const Scalar w = (1.0 - x2) * (1.0 - x2);
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> u = sign * zeta_t + (blend_speed * w) * reference;
  const Scalar norm = sqrt(u.squaredNorm());
  return u / norm;
}

}  // namespace impactbench::model
