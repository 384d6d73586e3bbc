#pragma once
// Small analytic systems for the Moreau–Jean and event-driven tests, independent of the
// project's rigid-body systems: planar disks and boxes above a (possibly inclined) ground line
// with disk–disk contacts, and a sphere on a horizontal plane with world-frame angular
// velocity. Ground contacts carry their acceleration-level drifts (the event-driven flow needs
// them); disk–disk contacts do not.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/model/lagrangian_system.hpp"

namespace impactbench::test_support {

/// A planar rigid body: a disk (radius) or a box (width × height), centre of mass at the centre.
struct PlanarTestBody {
  std::string name;
  double mass = 1.0;
  double radius = 0.0;  ///< disk when > 0
  double width = 0.0;   ///< box when radius == 0
  double height = 0.0;
  double inertia() const;
};

/// Bodies under gravity −g ŷ above the ground line through the origin with inward normal
/// (−sin α, cos α) (no ground when `has_ground` is false). Input k is a force of magnitude u_k
/// along `input_directions[k]` at the centre of body `input_bodies[k]`.
class PlanarTestWorld final : public model::LagrangianSystem<double> {
 public:
  PlanarTestWorld(std::vector<PlanarTestBody> bodies, double gravity, double friction,
                  double restitution, bool has_ground = true, double ground_angle = 0.0);
  void add_input(int body, const Eigen::Vector2d& direction);

  int num_positions() const override { return 3 * num_bodies(); }
  int num_velocities() const override { return 3 * num_bodies(); }
  int num_inputs() const override { return static_cast<int>(input_bodies_.size()); }
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

  int num_bodies() const { return static_cast<int>(bodies_.size()); }
  Eigen::Vector2d ground_normal() const;
  Eigen::Vector2d ground_tangent() const;  ///< (cos α, sin α): up the slope

 private:
  model::Contact<double> point_contact(int body, const Eigen::Vector2d& centre,
                                       const Eigen::Vector2d& arm, const Eigen::Vector2d& normal,
                                       double gap, int feature, std::string name) const;
  std::vector<std::string> body_names() const;
  std::vector<PlanarTestBody> bodies_;
  double gravity_, friction_, restitution_;
  bool has_ground_;
  double ground_angle_;
  std::vector<int> input_bodies_;
  std::vector<Eigen::Vector2d> input_directions_;
};

/// A solid sphere (radius R, mass m, I = 2/5 m R²) on the plane z = 0 under gravity −g ẑ.
/// q = [x, y, z, qw, qx, qy, qz], v = [v, ω] with ω in the world frame.
class SphereOnPlaneTestSystem final : public model::LagrangianSystem<double> {
 public:
  SphereOnPlaneTestSystem(double radius, double mass, double gravity, double friction,
                          double restitution);
  int num_positions() const override { return 7; }
  int num_velocities() const override { return 6; }
  int tangent_dim() const override { return 2; }
  SparseMatrix mass_matrix(const Vector& q) const override;
  Vector bias_forces(const Vector& q, const Vector& v) const override;
  Vector position_rate(const Vector& q, const Vector& v) const override;
  Vector integrate_position(const Vector& q, const Vector& v, const double& h) const override;
  void find_contacts(const Vector& q, const Vector& v, double margin,
                     std::vector<model::Contact<double>>& out) const override;
  double energy(const Vector& q, const Vector& v) const override;
  std::vector<std::string> position_names() const override;
  std::vector<std::string> velocity_names() const override;

 private:
  double radius_, mass_, gravity_, friction_, restitution_;
};

/// A point mass m at (x, y) held by a vertical spring k (rest height y0) and damper b, under
/// gravity −g ŷ, above the floor y = 0 (frictionless). H = (0, m g + k (y − y0) + b ẏ).
class SpringMassFloorTestSystem final : public model::LagrangianSystem<double> {
 public:
  SpringMassFloorTestSystem(double mass, double stiffness, double damping, double rest_height,
                            double gravity, double restitution);
  int num_positions() const override { return 2; }
  int num_velocities() const override { return 2; }
  int tangent_dim() const override { return 1; }
  SparseMatrix mass_matrix(const Vector& q) const override;
  Vector bias_forces(const Vector& q, const Vector& v) const override;
  Vector position_rate(const Vector& q, const Vector& v) const override {
    (void)q;
    return v;
  }
  Vector integrate_position(const Vector& q, const Vector& v, const double& h) const override {
    return q + h * v;
  }
  void find_contacts(const Vector& q, const Vector& v, double margin,
                     std::vector<model::Contact<double>>& out) const override;
  double energy(const Vector& q, const Vector& v) const override;
  std::vector<std::string> position_names() const override { return {"mass.x", "mass.y"}; }
  std::vector<std::string> velocity_names() const override { return {"mass.vx", "mass.vy"}; }

 private:
  double mass_, stiffness_, damping_, rest_height_, gravity_, restitution_;
};

}  // namespace impactbench::test_support
