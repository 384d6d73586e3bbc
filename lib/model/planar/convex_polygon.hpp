#pragma once
// A convex polygon in its body frame: vertices counter-clockwise about the centre of mass, and
// the outward unit normal of each edge k (from vertex k to vertex k+1). Boxes are built as
// polygons so that the narrow phase handles any convex polygon alike.
#include <vector>

#include <Eigen/Core>

namespace impactbench::model::planar {

struct ConvexPolygon {
  std::vector<Eigen::Vector2d> vertices;
  std::vector<Eigen::Vector2d> normals;  ///< normals[k] belongs to edge (k, k+1)

  int size() const { return static_cast<int>(vertices.size()); }
  const Eigen::Vector2d& vertex(int k) const {
    return vertices[static_cast<std::size_t>(k % size())];
  }
  /// Largest distance of a vertex from the centre: radius of the rotation-invariant bound.
  double bounding_radius() const;
};

/// Rectangle of full side lengths width x height centred on the origin; edge 0 is the bottom
/// face (normal −y), then right, top, left.
ConvexPolygon make_box_polygon(double width, double height);

}  // namespace impactbench::model::planar
