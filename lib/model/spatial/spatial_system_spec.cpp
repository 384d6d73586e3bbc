#include "lib/model/spatial/spatial_system_spec.hpp"

#include "lib/model/body_inertia.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace impactbench::model::spatial {
namespace {

[[noreturn]] void reject(const std::string& what, const std::string& name, const std::string& field,
                         const std::string& problem) {
  throw std::invalid_argument("spatial " + what + " '" + name + "': " + field + " " + problem);
}

std::string str(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

void require_positive(double x, const std::string& what, const std::string& name,
                      const std::string& field) {
  if (!std::isfinite(x) || x <= 0.0)
    reject(what, name, field, "must be finite and > 0 (got " + str(x) + ")");
}

void require_finite(const Eigen::Vector3d& x, const std::string& what, const std::string& name,
                    const std::string& field) {
  if (!x.allFinite()) reject(what, name, field, "must be finite");
}

// Orientations and normals are data typed by people; 1e-6 accepts six printed digits.
constexpr double kUnitTolerance = 1e-6;

void validate_body(const BodySpec& b) {
  const std::string what = "body";
  if (b.name.empty()) throw std::invalid_argument("spatial body: name must not be empty");
  require_positive(b.mass, what, b.name, "mass");
  if (b.shape == ShapeKind::kSphere) {
    require_positive(b.radius, what, b.name, "radius");
  } else if (b.shape == ShapeKind::kCuboid) {
    for (int i = 0; i < 3; ++i) require_positive(b.size(i), what, b.name, "size");
  } else {
    reject(what, b.name, "shape", "must be sphere or cuboid (planar shapes are not spatial)");
  }
  if (b.inertia) {
    if (const std::string problem = inertia_problem(*b.inertia); !problem.empty())
      reject(what, b.name, "inertia", problem);
  }
  require_finite(b.position, what, b.name, "position");
  require_finite(b.velocity, what, b.name, "velocity");
  require_finite(b.angular_velocity, what, b.name, "angular_velocity");
  const double norm = b.orientation.coeffs().norm();
  if (!std::isfinite(norm) || std::abs(norm - 1.0) > kUnitTolerance)
    reject(what, b.name, "orientation", "must be a unit quaternion (norm " + str(norm) + ")");
}

void validate_plane(const StaticPlaneSpec& p) {
  const std::string what = "plane";
  require_finite(p.point, what, p.name, "point");
  const double norm = p.normal.norm();
  if (!std::isfinite(norm) || std::abs(norm - 1.0) > kUnitTolerance)
    reject(what, p.name, "normal", "must be a unit vector (norm " + str(norm) + ")");
}

}  // namespace

void validate(const SpatialSystemSpec& spec) {
  std::set<std::string> names;
  for (const BodySpec& b : spec.bodies) {
    validate_body(b);
    if (!names.insert(b.name).second) reject("body", b.name, "name", "is used twice");
  }
  for (const StaticPlaneSpec& p : spec.planes) validate_plane(p);
  const Material& m = spec.material;
  if (!std::isfinite(m.friction) || m.friction < 0.0)
    throw std::invalid_argument("spatial material: friction must be finite and >= 0 (got " +
                                str(m.friction) + ")");
  if (!(m.restitution >= 0.0 && m.restitution <= 1.0))
    throw std::invalid_argument("spatial material: restitution must lie in [0, 1] (got " +
                                str(m.restitution) + ")");
  if (!std::isfinite(spec.gravity))
    throw std::invalid_argument("spatial system: gravity must be finite");
  for (const ForceInputSpec& in : spec.inputs) {
    if (!names.count(in.body)) reject("input", in.body, "body", "names no body of the system");
    const double norm = in.direction.norm();
    if (!std::isfinite(norm) || std::abs(norm - 1.0) > kUnitTolerance)
      reject("input", in.body, "direction", "must be a unit vector (norm " + str(norm) + ")");
  }
}

}  // namespace impactbench::model::spatial
