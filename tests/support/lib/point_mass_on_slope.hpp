#pragma once
// A point mass above a straight slope, the smallest system with one unilateral contact (the
// sensitivity tests' bouncing ball: flat, frictionless, e > 0; slope, friction and an input force
// along the slope are general parameters). Coordinates in the slope's frame:
// x along the slope (positive DOWN the slope), y its normal (up), so q = (x, y), v = (ẋ, ẏ).
// Gravity has components (g sin β, −g cos β); the one input is a force along +x.
//     M = m I,   H = (−m g sin β, m g cos β),   S = (1, 0)ᵀ,
//     gap h_n = y (y is the height of the contact point), w_n = (0, 1), W_t = (1, 0),
//     drifts 0. Energy T + V with V = −m g sin β x + m g cos β y.
// Templated on the scalar like the model layer so that the sensitivity module can use AD.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "lib/model/autodiff.hpp"
#include "lib/model/lagrangian_system.hpp"

namespace impactbench::test_support {

struct PointMassOnSlopeParameters {
  double mass = 1.0;         ///< m [kg]
  double gravity = 9.81;     ///< g [m/s²]
  double slope = 0.0;        ///< β [rad]
  double friction = 0.0;     ///< μ
  double restitution = 0.0;  ///< e
};

template <typename Scalar>
class PointMassOnSlope final : public model::LagrangianSystem<Scalar> {
 public:
  using typename model::LagrangianSystem<Scalar>::Vector;
  using typename model::LagrangianSystem<Scalar>::Matrix;
  using typename model::LagrangianSystem<Scalar>::SparseMatrix;

  explicit PointMassOnSlope(PointMassOnSlopeParameters parameters) : p_(parameters) {}

  int num_positions() const override { return 2; }
  int num_velocities() const override { return 2; }
  int num_inputs() const override { return 1; }
  int tangent_dim() const override { return 1; }

  SparseMatrix mass_matrix(const Vector& q) const override;
  Vector bias_forces(const Vector& q, const Vector& v) const override;
  Matrix input_matrix(const Vector& q) const override;
  Vector position_rate(const Vector& q, const Vector& v) const override;
  Vector integrate_position(const Vector& q, const Vector& v, const Scalar& h) const override;
  void find_contacts(const Vector& q, const Vector& v, double margin,
                     std::vector<model::Contact<Scalar>>& out) const override;
  Scalar energy(const Vector& q, const Vector& v) const override;
  std::vector<std::string> position_names() const override { return {"mass.x", "mass.y"}; }
  std::vector<std::string> velocity_names() const override { return {"mass.vx", "mass.vy"}; }

 private:
  PointMassOnSlopeParameters p_;
};

extern template class PointMassOnSlope<double>;
extern template class PointMassOnSlope<model::AutoDiff>;

}  // namespace impactbench::test_support
