#pragma once
// A planar scenario file's system as a hybrid model for the sensitivity tests: the double system
// and the same system on AD scalars for the Jacobians, both as the engines and the sensitivity
// command build them (lib/engines/system_builder), the initial state, and the scenario's input u(t)
// with its rate.
#include <memory>
#include <string>

#include <Eigen/Core>

#include "lib/engines/autodiff_system_builder.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/nominal_trajectory.hpp"

namespace impactbench::test_support {

class ScenarioHybridModel {
 public:
  /// Loads scenarios/<name>.toml with the overrides; planar rigid-body scenarios only (throws
  /// std::invalid_argument otherwise).
  explicit ScenarioHybridModel(const std::string& name,
                               const scenario::ParameterOverrides& overrides = {});
  ScenarioHybridModel(const ScenarioHybridModel&) = delete;
  ScenarioHybridModel& operator=(const ScenarioHybridModel&) = delete;

  const scenario::Scenario& scenario() const { return scenario_; }
  const sensitivity::MechanicalHybridModel& model() const { return *model_; }
  /// The double system, as the engines build it.
  const model::LagrangianSystem<double>& system() const { return *built_.system; }
  Eigen::VectorXd x0() const;
  /// u(t) of the scenario (zero-sized without inputs).
  sensitivity::InputFunction input() const;
  /// u̇(t) by a central difference (exact to round-off for inputs of degree ≤ 2 in t).
  sensitivity::InputFunction input_rate() const;
  /// The initial mode: contacts with |gap| ≤ 1e-12 at x0 get `closed` (slip phases take the
  /// sign of their tangential velocity, a stick request stays stick), the others are open.
  sensitivity::HybridMode initial_mode(sensitivity::ContactPhase closed) const;

 private:
  scenario::Scenario scenario_;
  engines::BuiltSystem built_;
  std::unique_ptr<const model::LagrangianSystem<model::AutoDiff>> system_ad_;
  std::unique_ptr<sensitivity::MechanicalHybridModel> model_;
};

}  // namespace impactbench::test_support
