#include "lib/output/column_names.hpp"

namespace impactbench::output {

namespace {
std::vector<std::string> names(const std::vector<model::BodySpec>& bodies,
                               std::initializer_list<const char*> coordinates) {
  std::vector<std::string> out;
  out.reserve(bodies.size() * coordinates.size());
  for (const auto& body : bodies)
    for (const char* coordinate : coordinates) out.push_back(body.name + "." + coordinate);
  return out;
}
}  // namespace

std::vector<std::string> rigid_body_position_names(const std::vector<model::BodySpec>& bodies,
                                                   bool spatial) {
  return spatial ? names(bodies, {"x", "y", "z", "qw", "qx", "qy", "qz"})
                 : names(bodies, {"x", "y", "theta"});
}

std::vector<std::string> rigid_body_velocity_names(const std::vector<model::BodySpec>& bodies,
                                                   bool spatial) {
  return spatial ? names(bodies, {"vx", "vy", "vz", "wx", "wy", "wz"})
                 : names(bodies, {"vx", "vy", "omega"});
}

}  // namespace impactbench::output
