#pragma once
// From a `system = "plank_box"` scenario to the plank–box model of lib/model/plank_box: the
// parameters (m_B, L_B, l_B, m_P, L_P, l_P, k_P, b_P, g; μ and e from the material) and the
// initial state q = (box.x, box.y, box.theta, plank.phi), v = (box.vx, box.vy, box.omega,
// plank.phi_dot) taken from the bodies `box` and `plank`.
#include <Eigen/Core>

#include "lib/model/plank_box/plank_box_parameters.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::scenario {

/// Throws std::invalid_argument if the scenario is not a plank_box scenario.
model::PlankBoxParameters plank_box_parameters(const Scenario& scenario);

struct PlankBoxInitialState {
  Eigen::Vector4d q;
  Eigen::Vector4d v;
};
PlankBoxInitialState plank_box_initial_state(const Scenario& scenario);

}  // namespace impactbench::scenario
