#pragma once
// How far the points of each rigid body can travel in a time h at velocities bounded per
// coordinate (|v_i| ≤ s_i): h (|s_v| + |s_ω| r), r the body's bounding radius about its centre,
// since a point at distance r moves at |v_centre + ω × r| ≤ |v_centre| + |ω| r. The planar and
// spatial systems' find_reachable_contacts widen their contact margins by it.
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace impactbench::model {

/// One reach per body [m] into `reach` (its storage reused); the velocities are `linear` then
/// `angular` coordinates per body (planar 2 and 1, spatial 3 and 3). Throws
/// std::invalid_argument, its message starting with `who`, when the bound has the wrong size or a
/// negative or NaN entry, or a reach is not finite.
template <typename RadiusOf, typename NameOf>
void body_reaches(const Eigen::VectorXd& speed_bound, double horizon, int bodies, int linear,
                  int angular, RadiusOf&& radius_of, NameOf&& name_of, std::string_view who,
                  std::vector<double>& reach) {
  const int per_body = linear + angular;
  if (speed_bound.size() != static_cast<Eigen::Index>(bodies) * per_body)
    throw std::invalid_argument(std::string(who) + "speed bound has size " +
                                std::to_string(speed_bound.size()) + ", expected " +
                                std::to_string(bodies * per_body));
  if (!(speed_bound.array() >= 0.0).all())
    throw std::invalid_argument(std::string(who) + "speed bound has a negative or NaN entry");
  reach.resize(static_cast<std::size_t>(bodies));
  for (int i = 0; i < bodies; ++i) {
    const double r =
        horizon * (speed_bound.segment(i * per_body, linear).norm() +
                   speed_bound.segment(i * per_body + linear, angular).norm() * radius_of(i));
    if (!(r >= 0.0 && std::isfinite(r)))
      throw std::invalid_argument(std::string(who) + "reach of body '" + name_of(i) +
                                  "' is not finite and >= 0");
    reach[static_cast<std::size_t>(i)] = r;
  }
}

}  // namespace impactbench::model
