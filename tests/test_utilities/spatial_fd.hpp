#pragma once
// Test helpers for the spatial rigid-body model: central differences along the velocity space
// (q ⊕ ε δv through integrate_position), a fixed-step RK4 for contact-free motion, and random
// poses.
#include <functional>
#include <random>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include "lib/model/lagrangian_system.hpp"

namespace impactbench::test {

/// (f(+ε) − f(−ε)) / 2ε; truncation error O(ε²), rounding O(u/ε).
inline double central_difference(const std::function<double(double)>& f, double eps) {
  return (f(eps) - f(-eps)) / (2 * eps);
}

inline Eigen::VectorXd central_difference(const std::function<Eigen::VectorXd(double)>& f,
                                          double eps) {
  return (f(eps) - f(-eps)) / (2 * eps);
}

/// A uniformly distributed unit quaternion, as (w, x, y, z).
inline Eigen::Vector4d random_unit_quaternion(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Vector4d q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized();
}

inline Eigen::Vector3d random_vector(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

/// One classical RK4 step of q̇ = N(q) v, M(q) v̇ = −H(q, v) (no contacts, no inputs). The
/// quaternions are renormalised afterwards by the caller if wanted.
inline void rk4_step(const model::LagrangianSystem<double>& system, Eigen::VectorXd& q,
                     Eigen::VectorXd& v, double h) {
  const auto rates = [&](const Eigen::VectorXd& qs, const Eigen::VectorXd& vs) {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> mass(system.mass_matrix(qs));
    return std::pair<Eigen::VectorXd, Eigen::VectorXd>(system.position_rate(qs, vs),
                                                       mass.solve(-system.bias_forces(qs, vs)));
  };
  const auto [dq1, dv1] = rates(q, v);
  const auto [dq2, dv2] = rates(q + 0.5 * h * dq1, v + 0.5 * h * dv1);
  const auto [dq3, dv3] = rates(q + 0.5 * h * dq2, v + 0.5 * h * dv2);
  const auto [dq4, dv4] = rates(q + h * dq3, v + h * dv3);
  q += h / 6 * (dq1 + 2 * dq2 + 2 * dq3 + dq4);
  v += h / 6 * (dv1 + 2 * dv2 + 2 * dv3 + dv4);
}

}  // namespace impactbench::test
