#pragma once
// Small analytic systems for the event-driven integrator's tests, independent of the model
// library's rigid-body systems: a disk or a box above a static line (planar), a ball above a
// plane (spatial, unit quaternion). Contacts are all potential contacts, whatever the margin.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/model/lagrangian_system.hpp"

namespace impactbench::test_utilities {

/// A static line through `point` with unit `normal` (planar) and a uniform material.
struct EventTestGround {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d normal = Eigen::Vector2d::UnitY();
  double friction = 0.0;
  double restitution = 0.0;
  double gravity = 9.81;  ///< along −y [m/s²]
  /// Tangent (n_y, −n_x): +x for a horizontal ground.
  Eigen::Vector2d tangent() const { return {normal.y(), -normal.x()}; }
};

/// A planar rigid body (x, y, θ) whose contact points are fixed body-frame points with a
/// rounding radius: a disk is one point at its centre with radius r, a box its four corners.
/// One input: a force along `input_direction` at the centre.
class EventPlanarBody final : public model::LagrangianSystem<double> {
 public:
  static EventPlanarBody disk(double radius, double mass, const EventTestGround& ground);
  static EventPlanarBody box(double width, double height, double mass,
                             const EventTestGround& ground);

  Eigen::Vector2d input_direction = Eigen::Vector2d::UnitX();

  int num_positions() const override { return 3; }
  int num_velocities() const override { return 3; }
  int num_inputs() const override { return 1; }
  int tangent_dim() const override { return 1; }
  SparseMatrix mass_matrix(const Vector& q) const override;
  Vector bias_forces(const Vector& q, const Vector& v) const override;
  Matrix input_matrix(const Vector& q) const override;
  Vector position_rate(const Vector& q, const Vector& v) const override;
  Vector integrate_position(const Vector& q, const Vector& v, const double& h) const override;
  void find_contacts(const Vector& q, const Vector& v, double margin,
                     std::vector<model::Contact<double>>& out) const override;
  double energy(const Vector& q, const Vector& v) const override;
  std::vector<std::string> position_names() const override;
  std::vector<std::string> velocity_names() const override;

  double mass = 1.0;
  double inertia = 1.0;
  double rounding = 0.0;                ///< radius around each contact point [m]
  std::vector<Eigen::Vector2d> points;  ///< body-frame contact points
  EventTestGround ground;
};

}  // namespace impactbench::test_utilities
