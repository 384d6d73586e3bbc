#pragma once
// One derivative size for every AutoDiff value the sensitivity model computes with.
//
// Eigen's AutoDiffScalar gives a constant an empty derivative vector and resizes it when it
// meets a sized one (make_coherent), but only when the empty operand is a plain vector: two
// constants combined in an unevaluated expression (−μ·s) and then met with a variable fail
// Eigen's size assertion, and with NDEBUG read out of bounds. The model therefore never lets an
// empty derivative vector into its arithmetic: constants are built with zero derivatives of the
// active size (the number of seeded variables), and every value the Lagrangian system returns is
// lifted to that size on entry. Eigen's own matrix products combine their constants (α = ±1) with
// a scalar factor they pull out of an operand, A * (μ s): such operands are evaluated into a
// vector first. For double every operation here is the identity.
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "lib/model/autodiff.hpp"
#include "lib/model/contact.hpp"

namespace impactbench::sensitivity {

template <typename Scalar>
class DerivativeSize {
 public:
  using Vec = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using Mat = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  static constexpr bool kAutoDiff = !std::is_same_v<Scalar, double>;

  /// `size`: the number of seeded variables (ignored for double).
  explicit DerivativeSize(Eigen::Index size = 0) : size_(kAutoDiff ? size : 0) {}

  Eigen::Index size() const { return size_; }

  /// `value` with zero derivatives of the active size.
  Scalar constant(double value) const {
    if constexpr (kAutoDiff)
      return Scalar(value, Eigen::VectorXd::Zero(size_));
    else
      return value;
  }

  /// x with an empty derivative vector replaced by zeros of the active size; a derivative
  /// vector of another non-zero size is a programming error.
  Scalar lift(const Scalar& x) const {
    if constexpr (kAutoDiff) {
      const Eigen::Index n = x.derivatives().size();
      if (n == size_) return x;
      if (n != 0)
        throw std::logic_error("sensitivity: a value with " + std::to_string(n) +
                               " derivatives where " + std::to_string(size_) + " are seeded");
      return constant(x.value());
    } else {
      return x;
    }
  }

  template <int Rows, int Cols, int Options, int MaxRows, int MaxCols>
  Eigen::Matrix<Scalar, Rows, Cols, Options, MaxRows, MaxCols> lift(
      Eigen::Matrix<Scalar, Rows, Cols, Options, MaxRows, MaxCols> x) const {
    if constexpr (kAutoDiff)
      for (Eigen::Index j = 0; j < x.cols(); ++j)
        for (Eigen::Index i = 0; i < x.rows(); ++i) x(i, j) = lift(x(i, j));
    return x;
  }

  /// The contact's gap, Jacobian blocks and drifts lifted.
  model::Contact<Scalar> lift(model::Contact<Scalar> c) const {
    c.gap = lift(c.gap);
    for (auto& block : c.blocks) block.rows = lift(block.rows);
    c.normal_drift = lift(c.normal_drift);
    c.tangent_drift = lift(c.tangent_drift);
    return c;
  }

  Vec zeros(Eigen::Index rows) const { return Vec::Constant(rows, constant(0.0)); }
  Mat zeros(Eigen::Index rows, Eigen::Index cols) const {
    return Mat::Constant(rows, cols, constant(0.0));
  }
  /// (value, …) of the given doubles, lifted.
  Vec vector(const std::vector<double>& values) const {
    Vec out(static_cast<Eigen::Index>(values.size()));
    for (Eigen::Index k = 0; k < out.size(); ++k)
      out(k) = constant(values[static_cast<std::size_t>(k)]);
    return out;
  }

 private:
  Eigen::Index size_ = 0;
};

}  // namespace impactbench::sensitivity
