#include "lib/scenario/plank_box_scenario.hpp"

#include <stdexcept>

namespace impactbench::scenario {

namespace {
void require_plank_box(const Scenario& scenario) {
  if (scenario.system != SystemKind::kPlankBox)
    throw std::invalid_argument("scenario '" + scenario.name + "' is not a plank_box scenario");
}
}  // namespace

model::PlankBoxParameters plank_box_parameters(const Scenario& scenario) {
  require_plank_box(scenario);
  model::PlankBoxParameters p;
  p.box_mass = scenario.parameter("m_B");
  p.box_length = scenario.parameter("L_B");
  p.box_height = scenario.parameter("l_B");
  p.plank_mass = scenario.parameter("m_P");
  p.plank_length = scenario.parameter("L_P");
  p.plank_thickness = scenario.parameter("l_P");
  p.plank_stiffness = scenario.parameter("k_P");
  p.plank_damping = scenario.parameter("b_P");
  p.gravity = scenario.parameter("g");
  p.friction = scenario.material.friction;
  p.restitution = scenario.material.restitution;
  p.validate();
  return p;
}

PlankBoxInitialState plank_box_initial_state(const Scenario& scenario) {
  require_plank_box(scenario);
  const model::BodySpec* box = scenario.find_body("box");
  const model::BodySpec* plank = scenario.find_body("plank");
  if (!box || !plank)  // the loader guarantees both; a hand-made Scenario may not
    throw std::invalid_argument("plank_box scenario '" + scenario.name +
                                "' needs bodies 'box' and 'plank'");
  PlankBoxInitialState state;
  state.q << box->position.x(), box->position.y(), box->angle, plank->angle;
  state.v << box->velocity.x(), box->velocity.y(), box->angular_velocity.z(),
      plank->angular_velocity.z();
  return state;
}

}  // namespace impactbench::scenario
