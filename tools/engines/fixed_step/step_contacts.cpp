#include "tools/engines/fixed_step/step_contacts.hpp"

#include <algorithm>

#include "tools/engines/fixed_step/contact_frame.hpp"

namespace impactbench::adapters {

std::vector<engines::ClosedContact> record_step_contacts(const ReferenceScene& scene,
                                                         const std::vector<PointContact>& contacts,
                                                         const std::vector<BodyState>& before,
                                                         const std::vector<BodyState>& after,
                                                         engines::StepRecord& step,
                                                         double& max_penetration) {
  std::vector<engines::ClosedContact> closed;  // one per pair of bodies
  std::vector<Eigen::Vector2d> pair_friction;
  for (const PointContact& c : contacts) {
    const Eigen::Vector3d& n = c.normal;
    const TangentFrame frame = tangent_frame(n, scene.planar);
    // After the step, at the point that moved with body 1.
    const Eigen::Vector3d p_after = moved_point(before, after, c.body1, c.point);
    const Eigen::Vector3d rel =
        point_velocity(after, c.body1, p_after) - point_velocity(after, c.body2, p_after);
    engines::ContactSample s;
    s.name = c.pair + "#" + std::to_string(step.contacts.size());
    s.gap = -c.depth;
    s.impulse_n = c.impulse.dot(n);
    s.impulse_t = frame.components(c.impulse - s.impulse_n * n);
    s.velocity_n = rel.dot(n);
    s.velocity_t = frame.components(rel - s.velocity_n * n);
    s.friction = scene.material.friction;
    s.restitution = scene.material.restitution;
    if (scene.planar) {       // planar: the in-plane tangent only (the out-of-plane one is the
      s.impulse_t.y() = 0.0;  // engine's 3D artefact, balanced by the plane constraint)
      s.velocity_t.y() = 0.0;
    }
    max_penetration = std::max(max_penetration, c.depth);
    s.velocity_n_before =
        (point_velocity(before, c.body1, c.point) - point_velocity(before, c.body2, c.point))
            .dot(n);
    const double approach = -s.velocity_n_before;
    const auto pair =
        std::find_if(closed.begin(), closed.end(), [&](const auto& p) { return p.name == c.pair; });
    const auto index = static_cast<std::size_t>(pair - closed.begin());
    if (pair == closed.end()) {
      closed.push_back({c.pair, approach, 0.0, 0.0});
      pair_friction.emplace_back(Eigen::Vector2d::Zero());
    }
    closed[index].approach_speed = std::max(closed[index].approach_speed, approach);
    closed[index].impulse_n += s.impulse_n;
    pair_friction[index] += s.impulse_t;
    step.contacts.push_back(std::move(s));
  }
  for (std::size_t i = 0; i < closed.size(); ++i)  // signed planar, magnitude spatial
    closed[i].impulse_t = scene.planar ? pair_friction[i].x() : pair_friction[i].norm();
  step.active_contacts = static_cast<int>(step.contacts.size());
  return closed;
}

}  // namespace impactbench::adapters
