#include "tools/cli/sensitivity_study.hpp"

#include <algorithm>
#include <cmath>

#include "lib/engines/autodiff_system_builder.hpp"
#include "lib/engines/settings/setting_fields.hpp"
#include "lib/sensitivity/event_driven_nominal.hpp"
#include "tools/cli/command.hpp"
#include "tools/engines/engine_names.hpp"

namespace impactbench::cli {

namespace ed = engines::event_driven;

namespace {

const scenario::Scenario& checked(const scenario::Scenario& s) {
  // The linearisation follows the event-driven run; a scenario that does not list that engine
  // is one it was not made for (and may take it minutes to refuse).
  if (!s.supports_engine(engine_name::kEvent))
    throw CliError("sensitivity needs the event-driven engine, which scenario '" + s.name +
                       "' does not list (its engines: " + engines::join_names(s.engines, "and") +
                       ")",
                   kExitFailure);
  return s;
}

}  // namespace

SensitivityStudy::SensitivityStudy(scenario::Scenario scenario, std::optional<double> duration,
                                   std::optional<double> tolerance, bool parameter_gains)
    : scenario_(std::move(scenario)),
      duration_(duration.value_or(scenario_.duration)),
      built_(engines::build_system(checked(scenario_))),
      system_ad_(engines::build_autodiff_system(scenario_)),
      model_(std::make_unique<sensitivity::MechanicalHybridModel>(*built_.system, *system_ad_,
                                                                  parameter_gains)) {
  const int m = model_->input_size();
  const scenario::Scenario& s = scenario_;
  input_ = [&s, m](double t) -> Eigen::VectorXd {
    return s.inputs.empty() ? Eigen::VectorXd(Eigen::VectorXd::Zero(m)) : s.input(t);
  };
  // μ̇ by a central difference of the scenario's input expression (smooth in t).
  input_rate_ = [this](double t) -> Eigen::VectorXd {
    const double h = 1e-6 * std::max(1.0, std::abs(t));
    return (input_(t + h) - input_(t - h)) / (2 * h);
  };
  ed::EventDrivenOptions options;
  options.relative_tolerance = options.absolute_tolerance = tolerance.value_or(1e-12);
  integrator_ = std::make_unique<ed::EventDrivenIntegrator>(*built_.system, options);
  const auto nominal_run = integrator_->simulate(built_.q0, built_.v0, input_, duration_);
  if (!nominal_run.succeeded())
    throw CliError("event-driven run failed: " + nominal_run.message, kExitFailure);
  linearisation_ = std::make_unique<sensitivity::TrajectorySensitivity>(
      *model_, sensitivity::nominal_from_event_run(*model_, *built_.system, nominal_run, input_,
                                                   input_rate_, duration_));
}

sensitivity::EndPointSensitivity SensitivityStudy::end_point() const {
  const int m = model_->input_size();
  const sensitivity::InputBasis constant = [m](double) {
    return Eigen::MatrixXd(Eigen::MatrixXd::Identity(m, m));
  };
  return linearisation_->end_point_sensitivity(constant);
}

}  // namespace impactbench::cli
