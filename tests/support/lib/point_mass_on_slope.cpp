#include "tests/support/lib/point_mass_on_slope.hpp"

#include <cmath>

namespace impactbench::test_support {

template <typename Scalar>
typename PointMassOnSlope<Scalar>::SparseMatrix PointMassOnSlope<Scalar>::mass_matrix(
    const Vector& /*q*/) const {
  SparseMatrix M(2, 2);
  M.insert(0, 0) = Scalar(p_.mass);
  M.insert(1, 1) = Scalar(p_.mass);
  M.makeCompressed();
  return M;
}

template <typename Scalar>
typename PointMassOnSlope<Scalar>::Vector PointMassOnSlope<Scalar>::bias_forces(
    const Vector& /*q*/, const Vector& /*v*/) const {
  Vector H(2);
  H << Scalar(-p_.mass * p_.gravity * std::sin(p_.slope)),
      Scalar(p_.mass * p_.gravity * std::cos(p_.slope));
  return H;
}

template <typename Scalar>
typename PointMassOnSlope<Scalar>::Matrix PointMassOnSlope<Scalar>::input_matrix(
    const Vector& /*q*/) const {
  Matrix S = Matrix::Zero(2, 1);
  S(0, 0) = Scalar(1.0);
  return S;
}

template <typename Scalar>
typename PointMassOnSlope<Scalar>::Vector PointMassOnSlope<Scalar>::position_rate(
    const Vector& /*q*/, const Vector& v) const {
  return v;
}

template <typename Scalar>
typename PointMassOnSlope<Scalar>::Vector PointMassOnSlope<Scalar>::integrate_position(
    const Vector& q, const Vector& v, const Scalar& h) const {
  return q + h * v;
}

template <typename Scalar>
void PointMassOnSlope<Scalar>::find_contacts(const Vector& q, const Vector& v, double /*margin*/,
                                             std::vector<model::Contact<Scalar>>& out) const {
  out.clear();
  model::Contact<Scalar> c;
  c.key = {0, -1, 0};
  c.name = "mass-slope";
  c.gap = q(1);
  model::JacobianBlock<Scalar> block;
  block.first_velocity = 0;
  block.rows = Matrix::Zero(2, 2);
  block.rows(0, 1) = Scalar(1.0);  // w_nᵀ = (0, 1)
  block.rows(1, 0) = Scalar(1.0);  // W_tᵀ = (1, 0)
  c.blocks.push_back(block);
  c.normal_drift = Scalar(0.0);
  c.tangent_drift = Vector::Zero(1);
  c.friction = p_.friction;
  c.restitution = p_.restitution;
  (void)v;
  out.push_back(std::move(c));
}

template <typename Scalar>
Scalar PointMassOnSlope<Scalar>::energy(const Vector& q, const Vector& v) const {
  return Scalar(0.5 * p_.mass) * v.squaredNorm() +
         Scalar(p_.mass * p_.gravity) *
             (Scalar(-std::sin(p_.slope)) * q(0) + Scalar(std::cos(p_.slope)) * q(1));
}

template class PointMassOnSlope<double>;
template class PointMassOnSlope<model::AutoDiff>;

}  // namespace impactbench::test_support
