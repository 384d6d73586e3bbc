#pragma once
// Central finite differences for checking analytic derivatives in tests: truncation error
// O(step²) plus rounding O(ε/step), about 1e-10 relative for step = 1e-6 on O(1) functions.
// The one implementation every test uses.
#include <algorithm>
#include <functional>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

namespace impactbench::test_support {

namespace detail {
/// The value type of a function's result: Eigen expressions evaluate to their plain matrix.
template <typename T>
struct Evaluated {
  using type = T;
};
template <typename T>
requires std::is_base_of_v<Eigen::EigenBase<T>, T>
struct Evaluated<T> {
  using type = typename T::PlainObject;
};
}  // namespace detail

/// d/ds f(s) at s = 0: (f(+step) − f(−step)) / 2 step, for f returning a double or an Eigen
/// vector (evaluated into its plain type, so no expression refers to temporaries).
template <typename Function>
auto central_difference(Function&& f, double step) {
  using Value = typename detail::Evaluated<std::decay_t<decltype(f(step))>>::type;
  const Value plus = f(step);
  const Value minus = f(-step);
  return Value((plus - minus) / (2.0 * step));
}

/// d/ds f(x + s direction) at s = 0: the directional derivative, e.g. of w_n(q)ᵀv along q̇ = v.
template <typename Function>
auto central_difference_along(Function&& f, const Eigen::VectorXd& x,
                              const Eigen::VectorXd& direction, double step = 1e-6) {
  return central_difference([&](double s) { return f(Eigen::VectorXd(x + s * direction)); }, step);
}

/// J(i, j) ≈ ∂f_i/∂x_j = (f(x + h e_j) − f(x − h e_j)) / 2h. `f` maps Eigen::VectorXd to
/// Eigen::VectorXd (any callable: lambda, std::function, functor).
template <typename Function>
Eigen::MatrixXd central_difference_jacobian(Function&& f, const Eigen::VectorXd& x,
                                            double step = 1e-6) {
  Eigen::MatrixXd jacobian;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    const Eigen::VectorXd column =
        central_difference_along(f, x, Eigen::VectorXd::Unit(x.size(), j), step);
    if (j == 0) jacobian.resize(column.size(), x.size());
    jacobian.col(j) = column;
  }
  return jacobian;
}

/// ∇f(x) of a scalar function by central differences.
template <typename Function>
Eigen::VectorXd central_difference_gradient(Function&& f, const Eigen::VectorXd& x,
                                            double step = 1e-6) {
  Eigen::VectorXd gradient(x.size());
  for (Eigen::Index j = 0; j < x.size(); ++j)
    gradient(j) = central_difference_along(f, x, Eigen::VectorXd::Unit(x.size(), j), step);
  return gradient;
}

/// Type-erased form for callers that store the function.
using VectorFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

/// max_i |a_i − b_i| / max(1, max_i |b_i|): the relative error used against `reference` b.
inline double relative_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  const double scale = std::max(1.0, b.cwiseAbs().maxCoeff());
  return (a - b).cwiseAbs().maxCoeff() / scale;
}

}  // namespace impactbench::test_support
