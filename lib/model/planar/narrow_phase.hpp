#pragma once
// Planar narrow phase on double values: for one shape pair, the active features whose gap is
// below the margin. Shapes are disks (centre, radius) and convex polygons; the static
// environment is a line through a point with outward unit normal.
//
// Normals point to body a: ground contacts have a = the body, disk–polygon a = the disk,
// polygon–polygon a = the incident polygon and b = the reference polygon (separating-axis test
// on the face normals, incident edge clipped against the reference face: up to two points).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/model/planar/contact_feature.hpp"
#include "lib/model/planar/convex_polygon.hpp"

namespace impactbench::model::planar {

struct Pose {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double angle = 0.0;
  Eigen::Matrix2d rotation() const;
  Eigen::Vector2d to_world(const Eigen::Vector2d& body_point) const;
};

/// One body as the narrow phase sees it; polygon == nullptr means a disk of `radius`.
struct ShapeRef {
  int index = -1;
  Pose pose;
  double radius = 0.0;
  const ConvexPolygon* polygon = nullptr;
};

struct Line {
  int index = 0;  ///< plane index, encoded in the feature id (index * kFeaturesPerPlane + local)
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d normal = Eigen::Vector2d::UnitY();
};

inline constexpr int kFeaturesPerPlane = 1000;

void collide_disk_line(const ShapeRef& disk, const Line& line, double margin,
                       std::vector<ContactFeature>& out);
void collide_polygon_line(const ShapeRef& polygon, const Line& line, double margin,
                          std::vector<ContactFeature>& out);
void collide_disk_disk(const ShapeRef& a, const ShapeRef& b, double margin,
                       std::vector<ContactFeature>& out);
/// Closest feature of the polygon to the disk centre: a face (centre outside in the face's
/// Voronoi region, or centre inside: the face of least penetration) or a vertex.
void collide_disk_polygon(const ShapeRef& disk, const ShapeRef& polygon, double margin,
                          std::vector<ContactFeature>& out);
void collide_polygon_polygon(const ShapeRef& a, const ShapeRef& b, double margin,
                             std::vector<ContactFeature>& out);

/// Dispatches on the shape kinds (the argument order of the pair does not matter).
void collide_shapes(const ShapeRef& a, const ShapeRef& b, double margin,
                    std::vector<ContactFeature>& out);
void collide_with_line(const ShapeRef& body, const Line& line, double margin,
                       std::vector<ContactFeature>& out);

}  // namespace impactbench::model::planar
