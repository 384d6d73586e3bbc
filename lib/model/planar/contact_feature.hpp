#pragma once
// The active feature of one planar contact, frozen by the narrow phase (which decides on plain
// double values) and then evaluated by evaluate_contact() with any scalar.
//
// Feature-freezing convention: every contact is a gap function between a material point of
// body a, p_a = c_a + R(θ_a) s_a, and a material point of body b, p_b = c_b + R(θ_b) s_b (or a
// fixed world point when b is the static environment), with s_a, s_b constant body-frame
// coordinates chosen at detection time:
//   kFixedNormal        h = nᵀ(p_a − p_b) − δ,  n a fixed world direction     (body–ground)
//   kNormalOfB          h = nᵀ(p_a − p_b) − δ,  n = R(θ_b) n_b turns with b   (faces of polygons)
//   kAlongSeparation    h = ‖p_a − p_b‖ − δ,    n = (p_a − p_b)/‖p_a − p_b‖   (disk–disk,
//   disk–vertex)
// w_n, ẇ_nᵀv, W_t and Ẇ_tᵀv are the exact derivatives of these functions; they hold as long as
// the narrow phase keeps choosing the same feature.
#include <Eigen/Core>

#include "lib/model/contact.hpp"

namespace impactbench::model::planar {

enum class NormalKind { kFixedNormal, kNormalOfB, kAlongSeparation };

struct ContactFeature {
  ContactKey key;  ///< body_a, body_b (−1: static environment), feature id
  NormalKind kind = NormalKind::kFixedNormal;
  Eigen::Vector2d s_a = Eigen::Vector2d::Zero();   ///< material point of a, body frame of a
  Eigen::Vector2d s_b = Eigen::Vector2d::Zero();   ///< of b in b's frame; world point if static
  Eigen::Vector2d n_b = Eigen::Vector2d::UnitY();  ///< world normal (fixed) or b-frame normal
  double offset = 0.0;    ///< δ subtracted from the distance (sum of radii involved) [m]
  double radius_a = 0.0;  ///< contact point x_c = p_a − radius_a n (on the surface of a) [m]
};

}  // namespace impactbench::model::planar
