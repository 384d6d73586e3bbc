#include "lib/output/column_names.hpp"

namespace impactbench::output {

namespace {
std::vector<std::string> names(const std::vector<std::string>& body_names,
                               std::initializer_list<const char*> coordinates) {
  std::vector<std::string> out;
  out.reserve(body_names.size() * coordinates.size());
  for (const auto& body : body_names)
    for (const char* coordinate : coordinates) out.push_back(body + "." + coordinate);
  return out;
}

std::vector<std::string> names_of(const std::vector<model::BodySpec>& bodies) {
  std::vector<std::string> out;
  out.reserve(bodies.size());
  for (const auto& body : bodies) out.push_back(body.name);
  return out;
}
}  // namespace

std::vector<std::string> rigid_body_position_names(const std::vector<std::string>& body_names,
                                                   bool spatial) {
  return spatial ? names(body_names, {"x", "y", "z", "qw", "qx", "qy", "qz"})
                 : names(body_names, {"x", "y", "theta"});
}

std::vector<std::string> rigid_body_velocity_names(const std::vector<std::string>& body_names,
                                                   bool spatial) {
  return spatial ? names(body_names, {"vx", "vy", "vz", "wx", "wy", "wz"})
                 : names(body_names, {"vx", "vy", "omega"});
}

std::vector<std::string> rigid_body_position_names(const std::vector<model::BodySpec>& bodies,
                                                   bool spatial) {
  return rigid_body_position_names(names_of(bodies), spatial);
}

std::vector<std::string> rigid_body_velocity_names(const std::vector<model::BodySpec>& bodies,
                                                   bool spatial) {
  return rigid_body_velocity_names(names_of(bodies), spatial);
}

}  // namespace impactbench::output
