#include "lib/model/body_inertia.hpp"

#include <cmath>
#include <string>

#include "solvers/common/number_text.hpp"  // not lib/output: it includes lib/model

namespace impactbench::model {

Eigen::Vector3d principal_inertia(const BodySpec& body) {
  if (body.inertia) return *body.inertia;
  const double m = body.mass;
  if (body.shape == ShapeKind::kSphere || body.shape == ShapeKind::kDisk)
    return Eigen::Vector3d::Constant(0.4 * m * body.radius * body.radius);
  const Eigen::Vector3d s2 = body.size.cwiseProduct(body.size);
  return m / 12.0 * Eigen::Vector3d(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
}

std::string inertia_problem(const Eigen::Vector3d& inertia) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(inertia(i)) || !(inertia(i) > 0.0))
      return "moments must be finite and > 0 (got " + output::number_text(inertia(i)) + ")";
  // Triangle inequality of principal moments, with a relative slack for printed values.
  for (int i = 0; i < 3; ++i) {
    const double others = inertia((i + 1) % 3) + inertia((i + 2) % 3);
    if (inertia(i) > others * (1 + 1e-9))
      return "moment " + output::number_text(inertia(i)) + " exceeds the sum of the other two (" +
             output::number_text(others) + "): no rigid body has it";
  }
  return {};
}

}  // namespace impactbench::model
