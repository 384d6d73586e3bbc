#include "lib/scenario/scenario_functions.hpp"

namespace impactbench::scenario {

Eigen::VectorXd ScenarioFunctions::input(double t) const {
  const std::lock_guard lock(mutex_);
  input_variables_.at("t") = t;
  Eigen::VectorXd u(static_cast<Eigen::Index>(inputs_.size()));
  for (std::size_t i = 0; i < inputs_.size(); ++i)
    u[static_cast<Eigen::Index>(i)] = inputs_[i].evaluate();
  return u;
}

double ScenarioFunctions::analytic(const std::string& name, int k) const {
  const std::lock_guard lock(mutex_);
  analytic_variables_.at("k") = k;
  return analytic_.evaluate(name);
}

}  // namespace impactbench::scenario
