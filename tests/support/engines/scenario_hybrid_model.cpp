#include "tests/support/engines/scenario_hybrid_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tests/support/lib/finite_difference.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::test_support {

ScenarioHybridModel::ScenarioHybridModel(const std::string& name,
                                         const scenario::ParameterOverrides& overrides)
    : scenario_(scenario::load_scenario_by_name(name, overrides)) {
  if (scenario_.dimension != scenario::Dimension::kPlanar ||
      scenario_.system != scenario::SystemKind::kRigidBodies)
    throw std::invalid_argument("ScenarioHybridModel: " + name +
                                " is not a planar rigid-body scenario");
  built_ = engines::build_system(scenario_);
  system_ad_ = engines::build_autodiff_system(scenario_);
  model_ = std::make_unique<sensitivity::MechanicalHybridModel>(*built_.system, *system_ad_);
}

Eigen::VectorXd ScenarioHybridModel::x0() const {
  Eigen::VectorXd x(built_.q0.size() + built_.v0.size());
  x << built_.q0, built_.v0;
  return x;
}

sensitivity::InputFunction ScenarioHybridModel::input() const {
  const int m = model_->input_size();
  return [this, m](double t) -> Eigen::VectorXd {
    return m == 0 ? Eigen::VectorXd() : scenario_.input(t);
  };
}

sensitivity::InputFunction ScenarioHybridModel::input_rate() const {
  const sensitivity::InputFunction u = input();
  return [u](double t) -> Eigen::VectorXd {
    const double h = 1e-3 * std::max(1.0, std::abs(t));
    return test_support::central_difference([&](double s) { return u(t + s); }, h);
  };
}

sensitivity::HybridMode ScenarioHybridModel::initial_mode(sensitivity::ContactPhase closed) const {
  using sensitivity::ContactPhase;
  const Eigen::VectorXd x = x0();
  const Eigen::VectorXd gaps = model_->gaps(x);
  const Eigen::MatrixXd zeta = model_->relative_velocities(x);
  sensitivity::HybridMode mode(static_cast<std::size_t>(gaps.size()), ContactPhase::kOpen);
  for (Eigen::Index i = 0; i < gaps.size(); ++i) {
    if (std::abs(gaps(i)) > 1e-12) continue;
    ContactPhase phase = closed;
    if (closed != ContactPhase::kStick && closed != ContactPhase::kOpen)
      phase = zeta(i, 1) >= 0.0 ? ContactPhase::kSlipPositive : ContactPhase::kSlipNegative;
    mode[static_cast<std::size_t>(i)] = phase;
  }
  return mode;
}

}  // namespace impactbench::test_support
