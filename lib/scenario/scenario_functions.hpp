#pragma once
// The compiled, time- or index-dependent parts of a scenario: the inputs u_k(t) and the
// analytic quantities. Shared (immutable) by copies of a Scenario; evaluation writes the
// variables t and k into private slots, so it is serialised by a mutex.
#include <mutex>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/scenario/expression.hpp"
#include "lib/scenario/named_expressions.hpp"

namespace impactbench::scenario {

class ScenarioFunctions {
 public:
  ScenarioFunctions() : analytic_(analytic_variables_) {}
  ScenarioFunctions(const ScenarioFunctions&) = delete;
  ScenarioFunctions& operator=(const ScenarioFunctions&) = delete;

  // Filled by the loader only.
  VariableTable& input_variables() { return input_variables_; }        ///< must hold "t"
  VariableTable& analytic_variables() { return analytic_variables_; }  ///< must hold "k"
  void add_input(Expression force) { inputs_.push_back(std::move(force)); }
  NamedExpressions& analytic() { return analytic_; }

  Eigen::VectorXd input(double t) const;
  double analytic(const std::string& name, int k) const;
  bool has_analytic(const std::string& name) const { return analytic_.contains(name); }
  bool analytic_reads(const std::string& name, const std::string& variable) const {
    return analytic_.reads(name, variable);
  }

 private:
  mutable std::mutex mutex_;
  mutable VariableTable input_variables_;
  mutable VariableTable analytic_variables_;
  std::vector<Expression> inputs_;
  NamedExpressions analytic_;
};

}  // namespace impactbench::scenario
