#pragma once
// A scenario file's system and initial state for the Moreau–Jean tests: planar or spatial rigid
// bodies, or the plank–box model. (The CLI has its own wiring; this one is for tests only.)
#include <memory>

#include <Eigen/Core>

#include "lib/model/lagrangian_system.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::testing {

struct ScenarioSystem {
  std::unique_ptr<model::LagrangianSystem<double>> system;
  Eigen::VectorXd q0;
  Eigen::VectorXd v0;
};

ScenarioSystem make_scenario_system(const scenario::Scenario& scenario);

}  // namespace impactbench::testing
