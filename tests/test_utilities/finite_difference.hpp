#pragma once
// Central finite differences for checking analytic derivatives in tests: truncation error
// O(step²) plus rounding O(ε/step), about 1e-10 relative for step = 1e-6 on O(1) functions.
#include <algorithm>
#include <functional>
#include <utility>

#include <Eigen/Core>

namespace impactbench::test {

/// J(i, j) ≈ ∂f_i/∂x_j = (f(x + h e_j) − f(x − h e_j)) / 2h. `f` maps Eigen::VectorXd to
/// Eigen::VectorXd (any callable: lambda, std::function, functor).
template <typename Function>
Eigen::MatrixXd central_difference_jacobian(Function&& f, const Eigen::VectorXd& x,
                                            double step = 1e-6) {
  Eigen::MatrixXd jacobian;
  Eigen::VectorXd xp = x;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    xp(j) = x(j) + step;
    const Eigen::VectorXd f_plus = f(xp);
    xp(j) = x(j) - step;
    const Eigen::VectorXd f_minus = f(xp);
    xp(j) = x(j);
    if (j == 0) jacobian.resize(f_plus.size(), x.size());
    jacobian.col(j) = (f_plus - f_minus) / (2.0 * step);
  }
  return jacobian;
}

/// d/ds f(x + s direction) at s = 0: the directional derivative, e.g. of w_n(q)ᵀv along q̇ = v.
template <typename Function>
Eigen::VectorXd central_difference_along(Function&& f, const Eigen::VectorXd& x,
                                         const Eigen::VectorXd& direction, double step = 1e-6) {
  return (f(Eigen::VectorXd(x + step * direction)) - f(Eigen::VectorXd(x - step * direction))) /
         (2.0 * step);
}

/// Type-erased form for callers that store the function.
using VectorFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

/// max_i |a_i − b_i| / max(1, max_i |b_i|): the relative error used against `reference` b.
inline double relative_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  const double scale = std::max(1.0, b.cwiseAbs().maxCoeff());
  return (a - b).cwiseAbs().maxCoeff() / scale;
}

}  // namespace impactbench::test
