#include "tools/engines/fixed_step/scene_state.hpp"

#include <cmath>
#include <utility>

#include "lib/output/column_names.hpp"

namespace impactbench::adapters {
namespace {

// Names of the free bodies with the hinged ones' columns after them, as our plank–box orders
// its coordinates (box.x, box.y, box.theta, plank.phi).
std::vector<std::string> names(const ReferenceScene& scene, bool positions) {
  std::vector<std::string> free_bodies, hinged;
  for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i)
    (hinge_of(scene, i) ? hinged : free_bodies).push_back(scene.bodies[i].name);
  std::vector<std::string> out =
      positions ? output::rigid_body_position_names(free_bodies, !scene.planar)
                : output::rigid_body_velocity_names(free_bodies, !scene.planar);
  for (const std::string& body : hinged) out.push_back(body + (positions ? ".phi" : ".omega"));
  return out;
}

}  // namespace

std::vector<std::string> scene_position_names(const ReferenceScene& scene) {
  return names(scene, true);
}

std::vector<std::string> scene_velocity_names(const ReferenceScene& scene) {
  return names(scene, false);
}

double planar_angle(const Eigen::Quaterniond& orientation) {
  return 2.0 * std::atan2(orientation.z(), orientation.w());
}

Eigen::Vector3d point_velocity(const std::vector<BodyState>& states, int body,
                               const Eigen::Vector3d& p) {
  if (body < 0) return Eigen::Vector3d::Zero();
  const BodyState& s = states[body];
  return s.velocity + s.angular_velocity.cross(p - s.position);
}

Eigen::Vector3d moved_point(const std::vector<BodyState>& before,
                            const std::vector<BodyState>& after, int body,
                            const Eigen::Vector3d& p) {
  if (body < 0) return p;
  const BodyState &b = before[body], &a = after[body];
  return a.position + a.orientation * (b.orientation.inverse() * (p - b.position));
}

SceneCoordinates scene_coordinates(const ReferenceScene& scene,
                                   const std::vector<BodyState>& bodies) {
  const int np = scene.planar ? 3 : 7, nv = scene.planar ? 3 : 6;
  const auto free_count = static_cast<Eigen::Index>(bodies.size() - scene.hinges.size());
  SceneCoordinates c;
  c.q.resize(np * free_count + static_cast<Eigen::Index>(scene.hinges.size()));
  c.v.resize(nv * free_count + static_cast<Eigen::Index>(scene.hinges.size()));
  Eigen::Index free_index = 0, hinge_index = np * free_count, hinge_rate = nv * free_count;
  for (int i = 0; i < static_cast<int>(bodies.size()); ++i) {
    const BodyState& b = bodies[i];
    const double angle = b.angle.value_or(planar_angle(b.orientation));
    if (hinge_of(scene, i)) {
      c.q[hinge_index++] = angle;
      c.v[hinge_rate++] = b.angular_velocity.z();
    } else if (scene.planar) {
      c.q.segment<3>(3 * free_index) << b.position.x(), b.position.y(), angle;
      c.v.segment<3>(3 * free_index) << b.velocity.x(), b.velocity.y(), b.angular_velocity.z();
      ++free_index;
    } else {
      const Eigen::Quaterniond& r = b.orientation;
      c.q.segment<7>(7 * free_index) << b.position, r.w(), r.x(), r.y(), r.z();
      c.v.segment<6>(6 * free_index) << b.velocity, b.angular_velocity;
      ++free_index;
    }
  }
  return c;
}

engines::RunResult scene_result(const std::string& engine, const ReferenceScene& scene,
                                const engines::RecordingOptions& recording) {
  engines::RunResult result;
  result.engine = engine;
  result.recording = recording;
  result.trajectory.position_names = scene_position_names(scene);
  result.trajectory.velocity_names = scene_velocity_names(scene);
  return result;
}

void add_scene_sample(engines::RunResult& result, const ReferenceScene& scene,
                      const std::vector<BodyState>& bodies, double t) {
  SceneCoordinates c = scene_coordinates(scene, bodies);
  const double energy = scene.energy ? scene.energy(c.q, c.v) : std::nan("");
  result.add_sample(t, std::move(c.q), std::move(c.v), energy);
}

}  // namespace impactbench::adapters
