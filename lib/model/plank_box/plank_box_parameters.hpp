#pragma once
// Physical parameters of the plank–box model (source appendix F, F.4–F.6 and Figure F.1), with
// SI units and defaults of a 1 kg box on a 1 m, 2 kg plank held by a stiff torsional spring.
#include <optional>

namespace impactbench::model {

struct PlankBoxParameters {
  // The box (fully actuated rigid rectangle).
  double box_mass = 1.0;    ///< m_B [kg], > 0
  double box_length = 0.2;  ///< L_B [m], > 0: side along the plank (body x axis)
  double box_height = 0.1;  ///< l_B [m], > 0: side normal to the plank (body y axis)

  // The plank, hinged to the world at one end (the origin), its centre of mass at L_P/2 along it.
  double plank_mass = 2.0;        ///< m_P [kg], > 0
  double plank_length = 1.0;      ///< L_P [m], > 0: hinge to free end
  double plank_thickness = 0.02;  ///< l_P [m], > 0: the top surface is l_P/2 above the hinge line
  /// J_P [kg·m²], > 0: inertia about the plank's centre of mass. Empty: uniform slab,
  /// m_P (L_P² + l_P²) / 12 (0.16673 kg·m² with the defaults).
  std::optional<double> plank_inertia;
  double plank_stiffness = 200.0;  ///< k_P [N·m/rad], ≥ 0: restoring torque −k_P φ
  double plank_damping = 2.0;      ///< b_P [N·m·s/rad], ≥ 0: restoring torque −b_P φ̇

  double gravity = 9.81;     ///< g [m/s²], ≥ 0, acting along −y of the world
  double friction = 0.5;     ///< μ [-], ≥ 0, both contacts C_L and C_R
  double restitution = 0.0;  ///< e [-] in [0, 1], Newton's law; 0 reproduces the source (B.20)

  /// J_B = m_B (L_B² + l_B²) / 12 [kg·m²]: uniform rectangle about its centre.
  double box_inertia() const;
  /// J_P, from `plank_inertia` or the uniform-slab default.
  double plank_centre_inertia() const;
  /// m_P L_P² / 4 + J_P [kg·m²]: the plank's inertia about the hinge (F.4, parallel axes).
  double plank_hinge_inertia() const;

  /// Throws std::invalid_argument naming the first field that is non-finite or out of range.
  void validate() const;
};

}  // namespace impactbench::model
