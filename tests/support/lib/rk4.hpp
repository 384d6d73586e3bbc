#pragma once
// Classical fixed-step Runge–Kutta (RK4) for smooth ODEs ẋ = f(t, x): the reference
// integrator of the tests (local error O(h⁵), global O(h⁴)). No step control, no events: use it
// only on intervals where the right-hand side is smooth.
#include <functional>
#include <stdexcept>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include "lib/model/lagrangian_system.hpp"

namespace impactbench::test_support {

using StateDerivative = std::function<Eigen::VectorXd(double t, const Eigen::VectorXd& x)>;

/// The increment x(t + h) − x(t) of one RK4 step (for callers that sum with compensation).
inline Eigen::VectorXd rk4_increment(const StateDerivative& f, double t, const Eigen::VectorXd& x,
                                     double h) {
  const Eigen::VectorXd k1 = f(t, x);
  const Eigen::VectorXd k2 = f(t + 0.5 * h, x + 0.5 * h * k1);
  const Eigen::VectorXd k3 = f(t + 0.5 * h, x + 0.5 * h * k2);
  const Eigen::VectorXd k4 = f(t + h, x + h * k3);
  return (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

/// One RK4 step of size h from (t, x).
inline Eigen::VectorXd rk4_step(const StateDerivative& f, double t, const Eigen::VectorXd& x,
                                double h) {
  return x + rk4_increment(f, t, x, h);
}

/// x(t1) from x(t0) = x0 in `steps` equal steps. `observe(t, x)`, if given, is called at t0 and
/// after every step.
inline Eigen::VectorXd integrate_rk4(
    const StateDerivative& f, double t0, const Eigen::VectorXd& x0, double t1, int steps,
    const std::function<void(double, const Eigen::VectorXd&)>& observe = {}) {
  if (steps <= 0) throw std::invalid_argument("integrate_rk4: steps must be > 0");
  const double h = (t1 - t0) / steps;
  Eigen::VectorXd x = x0;
  if (observe) observe(t0, x);
  for (int i = 0; i < steps; ++i) {
    const double t = t0 + i * h;
    x = rk4_step(f, t, x, h);
    if (observe) observe(t + h, x);
  }
  return x;
}

/// One RK4 step of a system's contact-free motion q̇ = N(q) v, M(q) v̇ = −H(q, v) (no inputs),
/// on the state (q, v). Quaternions are not renormalised (the caller does if it wants).
inline void rk4_step(const model::LagrangianSystem<double>& system, Eigen::VectorXd& q,
                     Eigen::VectorXd& v, double h) {
  const Eigen::Index nq = q.size(), nv = v.size();
  const StateDerivative rates = [&](double, const Eigen::VectorXd& x) {
    const Eigen::VectorXd qs = x.head(nq), vs = x.tail(nv);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> mass(system.mass_matrix(qs));
    Eigen::VectorXd dx(nq + nv);
    dx << system.position_rate(qs, vs), mass.solve(-system.bias_forces(qs, vs));
    return dx;
  };
  Eigen::VectorXd x(nq + nv);
  x << q, v;
  x = rk4_step(rates, 0.0, x, h);
  q = x.head(nq);
  v = x.tail(nv);
}

}  // namespace impactbench::test_support
