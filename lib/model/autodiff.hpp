#pragma once
// The one automatic-differentiation scalar of the models (forward mode, derivative vector of
// dynamic size), and the plain double behind a model scalar. Geometry decisions (which feature is
// closest, is a gap below the margin) are made on value_of only, so that they are constant in a
// neighbourhood and derivatives flow through the formulas alone.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace impactbench::model {

using AutoDiff = Eigen::AutoDiffScalar<Eigen::VectorXd>;

inline double value_of(double x) {
  return x;
}

template <typename Derivatives>
double value_of(const Eigen::AutoDiffScalar<Derivatives>& x) {
  return x.value();
}

}  // namespace impactbench::model
