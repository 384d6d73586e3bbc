#pragma once
// The deepest penetration of a run, measured on our model's geometry: every contact the
// model finds in every sample (not only the contacts an engine put into its contact problem),
// so that an impact a time-stepper missed shows at its true depth.
#include <vector>

#include "lib/model/lagrangian_system.hpp"

namespace impactbench::metrics {

/// The deepest penetration as states arrive (an engine's every recorded state, whether or not
/// the sample is kept): max(0, −gap) over every contact of every state offered [m].
class PenetrationTracker {
 public:
  explicit PenetrationTracker(const model::LagrangianSystem<double>& system) : system_(system) {}
  void add(const Eigen::VectorXd& q, const Eigen::VectorXd& v);
  double deepest() const { return deepest_; }

 private:
  const model::LagrangianSystem<double>& system_;
  std::vector<model::Contact<double>> contacts_;  // reused
  double deepest_ = 0.0;
};

}  // namespace impactbench::metrics
