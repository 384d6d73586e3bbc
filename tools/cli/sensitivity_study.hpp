#pragma once
// The linearisation behind `impactbench sensitivity`, as a library call that the program and the
// Python module share: the scenario's event-driven run (tolerance 1e-12 unless given) and the
// first-order sensitivity along it (lib/sensitivity), with the systems, model and input the
// prediction of a perturbed run needs. Planar and spatial rigid-body scenarios and the
// plank–box; with parameter_gains the friction coefficient and restitution join the state.
#include <memory>
#include <optional>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/engines/system_builder.hpp"
#include "lib/model/lagrangian_system.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"

namespace impactbench::cli {

class SensitivityStudy {
 public:
  /// Runs and linearises; throws CliError with the program's message and exit code for a
  /// scenario it cannot linearise or a failed run. Not copyable: its parts refer to each other.
  SensitivityStudy(scenario::Scenario scenario, std::optional<double> duration,
                   std::optional<double> tolerance, bool parameter_gains = false);
  SensitivityStudy(const SensitivityStudy&) = delete;
  SensitivityStudy& operator=(const SensitivityStudy&) = delete;

  const scenario::Scenario& scenario() const { return scenario_; }
  double duration() const { return duration_; }
  const engines::BuiltSystem& built() const { return built_; }
  const sensitivity::MechanicalHybridModel& model() const { return *model_; }
  const engines::event_driven::EventDrivenIntegrator& integrator() const { return *integrator_; }
  const sensitivity::InputFunction& input() const { return input_; }
  const sensitivity::TrajectorySensitivity& linearisation() const { return *linearisation_; }
  /// The end-point matrices for a constant input perturbation (one column per input channel).
  sensitivity::EndPointSensitivity end_point() const;

 private:
  scenario::Scenario scenario_;
  double duration_;
  engines::BuiltSystem built_;
  std::unique_ptr<const model::LagrangianSystem<sensitivity::AutoDiff>> system_ad_;
  std::unique_ptr<sensitivity::MechanicalHybridModel> model_;
  sensitivity::InputFunction input_, input_rate_;
  std::unique_ptr<engines::event_driven::EventDrivenIntegrator> integrator_;
  std::unique_ptr<sensitivity::TrajectorySensitivity> linearisation_;
};

}  // namespace impactbench::cli
