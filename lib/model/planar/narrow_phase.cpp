#include "lib/model/planar/narrow_phase.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace impactbench::model::planar {
namespace {

// Signed distance of the most separated face of `ref` from `other` (min over other's vertices),
// and that face: the separating-axis test restricted to ref's face normals.
std::pair<double, int> max_face_separation(const ShapeRef& ref, const ShapeRef& other) {
  const Eigen::Matrix2d r_ref = ref.pose.rotation();
  double best = -std::numeric_limits<double>::infinity();
  int best_face = 0;
  for (int k = 0; k < ref.polygon->size(); ++k) {
    const Eigen::Vector2d n = r_ref * ref.polygon->normals[static_cast<std::size_t>(k)];
    const Eigen::Vector2d v = ref.pose.to_world(ref.polygon->vertex(k));
    double sep = std::numeric_limits<double>::infinity();
    for (const auto& w : other.polygon->vertices)
      sep = std::min(sep, n.dot(other.pose.to_world(w) - v));
    if (sep > best) {
      best = sep;
      best_face = k;
    }
  }
  return {best, best_face};
}

}  // namespace

Eigen::Matrix2d Pose::rotation() const {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return (Eigen::Matrix2d() << c, -s, s, c).finished();
}

Eigen::Vector2d Pose::to_world(const Eigen::Vector2d& body_point) const {
  return centre + rotation() * body_point;
}

void collide_disk_line(const ShapeRef& disk, const Line& line, double margin,
                       std::vector<ContactFeature>& out) {
  const double gap = line.normal.dot(disk.pose.centre - line.point) - disk.radius;
  if (gap > margin) return;
  ContactFeature f;
  f.key = {disk.index, -1, line.index * kFeaturesPerPlane};
  f.kind = NormalKind::kFixedNormal;
  f.s_b = line.point;
  f.n_b = line.normal;
  f.offset = f.radius_a = disk.radius;
  out.push_back(std::move(f));
}

void collide_polygon_line(const ShapeRef& polygon, const Line& line, double margin,
                          std::vector<ContactFeature>& out) {
  for (int k = 0; k < polygon.polygon->size(); ++k) {
    const Eigen::Vector2d& s = polygon.polygon->vertex(k);
    if (line.normal.dot(polygon.pose.to_world(s) - line.point) > margin) continue;
    ContactFeature f;
    f.key = {polygon.index, -1, line.index * kFeaturesPerPlane + k};
    f.kind = NormalKind::kFixedNormal;
    f.s_a = s;
    f.s_b = line.point;
    f.n_b = line.normal;
    out.push_back(std::move(f));
  }
}

void collide_disk_disk(const ShapeRef& a, const ShapeRef& b, double margin,
                       std::vector<ContactFeature>& out) {
  const double distance = (a.pose.centre - b.pose.centre).norm();
  if (distance - a.radius - b.radius > margin) return;
  ContactFeature f;
  f.key = {a.index, b.index, 0};
  f.offset = a.radius + b.radius;
  f.radius_a = a.radius;
  // Coincident centres leave the direction undefined; fall back to a vertical normal frozen in
  // the world (h is then only a first-order model, but the state is already far from valid).
  f.kind = distance > 1e-12 * f.offset ? NormalKind::kAlongSeparation : NormalKind::kFixedNormal;
  out.push_back(std::move(f));
}

void collide_disk_polygon(const ShapeRef& disk, const ShapeRef& polygon, double margin,
                          std::vector<ContactFeature>& out) {
  const ConvexPolygon& poly = *polygon.polygon;
  const Eigen::Vector2d x =
      polygon.pose.rotation().transpose() * (disk.pose.centre - polygon.pose.centre);
  double max_sep = -std::numeric_limits<double>::infinity();
  int max_face = 0;
  for (int k = 0; k < poly.size(); ++k) {
    const double sep = poly.normals[static_cast<std::size_t>(k)].dot(x - poly.vertex(k));
    if (sep > max_sep) {
      max_sep = sep;
      max_face = k;
    }
  }
  if (max_sep - disk.radius > margin) return;  // the distance is at least max_sep

  int face = max_face;  // centre inside: face of least penetration
  int vertex = -1;
  double gap = max_sep - disk.radius;
  if (max_sep > 0.0) {  // centre outside: closest point of the boundary
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < poly.size(); ++k) {
      const Eigen::Vector2d e = poly.vertex(k + 1) - poly.vertex(k);
      const double t = std::clamp(e.dot(x - poly.vertex(k)) / e.squaredNorm(), 0.0, 1.0);
      const double dist = (x - (poly.vertex(k) + t * e)).norm();
      if (dist < best) {
        best = dist;
        face = k;
        vertex = t <= 0.0 ? k : (t >= 1.0 ? (k + 1) % poly.size() : -1);
      }
    }
    gap = best - disk.radius;
    if (gap > margin) return;
  }

  ContactFeature f;
  f.offset = f.radius_a = disk.radius;
  if (vertex >= 0) {
    f.key = {disk.index, polygon.index, poly.size() + vertex};
    f.kind = NormalKind::kAlongSeparation;
    f.s_b = poly.vertex(vertex);
  } else {
    f.key = {disk.index, polygon.index, face};
    f.kind = NormalKind::kNormalOfB;
    f.s_b = poly.vertex(face);
    f.n_b = poly.normals[static_cast<std::size_t>(face)];
  }
  out.push_back(std::move(f));
}

void collide_polygon_polygon(const ShapeRef& a, const ShapeRef& b, double margin,
                             std::vector<ContactFeature>& out) {
  const auto [sep_a, face_a] = max_face_separation(a, b);
  if (sep_a > margin) return;
  const auto [sep_b, face_b] = max_face_separation(b, a);
  if (sep_b > margin) return;

  // Prefer a's face unless b's is clearly less penetrating, so that near-ties keep one choice.
  const double tie_tolerance = 1e-9 * (1.0 + std::abs(sep_a));
  const bool b_is_reference = sep_b > sep_a + tie_tolerance;
  const ShapeRef& ref = b_is_reference ? b : a;
  const ShapeRef& inc = b_is_reference ? a : b;
  const int ref_face = b_is_reference ? face_b : face_a;

  const Eigen::Matrix2d r_ref = ref.pose.rotation();
  const Eigen::Matrix2d r_inc = inc.pose.rotation();
  const Eigen::Vector2d n = r_ref * ref.polygon->normals[static_cast<std::size_t>(ref_face)];

  // Incident face: the face of the other polygon most anti-parallel to the reference normal.
  int inc_face = 0;
  double most_negative = std::numeric_limits<double>::infinity();
  for (int j = 0; j < inc.polygon->size(); ++j) {
    const double c = n.dot(r_inc * inc.polygon->normals[static_cast<std::size_t>(j)]);
    if (c < most_negative) {
      most_negative = c;
      inc_face = j;
    }
  }

  // Clip the incident edge to the slab between the side planes of the reference face.
  const Eigen::Vector2d r1 = ref.pose.to_world(ref.polygon->vertex(ref_face));
  const Eigen::Vector2d r2 = ref.pose.to_world(ref.polygon->vertex(ref_face + 1));
  const Eigen::Vector2d tangent = (r2 - r1).normalized();
  std::array<Eigen::Vector2d, 2> points = {inc.pose.to_world(inc.polygon->vertex(inc_face)),
                                           inc.pose.to_world(inc.polygon->vertex(inc_face + 1))};
  const std::array<std::pair<Eigen::Vector2d, double>, 2> side_planes = {
      std::pair{Eigen::Vector2d(-tangent), -tangent.dot(r1)}, std::pair{tangent, tangent.dot(r2)}};
  for (const auto& [m, c] : side_planes) {
    const double d0 = m.dot(points[0]) - c;
    const double d1 = m.dot(points[1]) - c;
    if (d0 > 0.0 && d1 > 0.0) return;  // the incident edge misses the reference face
    if (d0 > 0.0) points[0] += (d0 / (d0 - d1)) * (points[1] - points[0]);
    if (d1 > 0.0) points[1] += (d1 / (d1 - d0)) * (points[0] - points[1]);
  }

  for (int slot = 0; slot < 2; ++slot) {
    const Eigen::Vector2d& p = points[static_cast<std::size_t>(slot)];
    if (n.dot(p - r1) > margin) continue;
    ContactFeature f;
    f.key = {inc.index, ref.index, 2 * ref_face + slot};
    f.kind = NormalKind::kNormalOfB;
    f.s_a =
        r_inc.transpose() * (p - inc.pose.centre);  // frozen material point of the incident body
    f.s_b = ref.polygon->vertex(ref_face);
    f.n_b = ref.polygon->normals[static_cast<std::size_t>(ref_face)];
    out.push_back(std::move(f));
  }
}

void collide_shapes(const ShapeRef& a, const ShapeRef& b, double margin,
                    std::vector<ContactFeature>& out) {
  const bool a_disk = a.polygon == nullptr;
  const bool b_disk = b.polygon == nullptr;
  if (a_disk && b_disk) return collide_disk_disk(a, b, margin, out);
  if (a_disk) return collide_disk_polygon(a, b, margin, out);
  if (b_disk) return collide_disk_polygon(b, a, margin, out);
  collide_polygon_polygon(a, b, margin, out);
}

void collide_with_line(const ShapeRef& body, const Line& line, double margin,
                       std::vector<ContactFeature>& out) {
  if (body.polygon == nullptr) return collide_disk_line(body, line, margin, out);
  collide_polygon_line(body, line, margin, out);
}

}  // namespace impactbench::model::planar
