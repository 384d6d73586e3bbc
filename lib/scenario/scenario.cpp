#include "lib/scenario/scenario.hpp"

#include <algorithm>
#include <stdexcept>

#include "lib/scenario/scenario_functions.hpp"

namespace impactbench::scenario {

std::string to_string(Dimension dimension) {
  return dimension == Dimension::kPlanar ? "planar" : "spatial";
}

std::string to_string(SystemKind system) {
  return system == SystemKind::kRigidBodies ? "rigid_bodies" : "plank_box";
}

const Parameter* Scenario::find_parameter(const std::string& parameter_name) const {
  for (const auto& p : parameters)
    if (p.name == parameter_name) return &p;
  return nullptr;
}

double Scenario::parameter(const std::string& parameter_name) const {
  if (const Parameter* p = find_parameter(parameter_name)) return p->value;
  std::string valid;
  for (const auto& p : parameters) valid += (valid.empty() ? "" : ", ") + p.name;
  throw std::invalid_argument("scenario '" + name + "' has no parameter '" + parameter_name +
                              "' (valid: " + valid + ")");
}

const model::BodySpec* Scenario::find_body(const std::string& body_name) const {
  for (const auto& body : bodies)
    if (body.name == body_name) return &body;
  return nullptr;
}

bool Scenario::supports_engine(const std::string& engine) const {
  return std::find(engines.begin(), engines.end(), engine) != engines.end();
}

Eigen::VectorXd Scenario::input(double t) const {
  if (!functions) return Eigen::VectorXd::Zero(static_cast<Eigen::Index>(inputs.size()));
  return functions->input(t);
}

bool Scenario::has_analytic(const std::string& quantity) const {
  return functions && functions->has_analytic(quantity);
}

double Scenario::analytic(const std::string& quantity, int k) const {
  if (!has_analytic(quantity)) {
    std::string valid;
    for (const auto& q : analytic_quantities) valid += (valid.empty() ? "" : ", ") + q.name;
    throw std::invalid_argument("scenario '" + name + "' has no analytic quantity '" + quantity +
                                "' (valid: " + valid + ")");
  }
  return functions->analytic(quantity, k);
}

}  // namespace impactbench::scenario
