#include "lib/model/planar/convex_polygon.hpp"

#include <algorithm>

namespace impactbench::model::planar {

double ConvexPolygon::bounding_radius() const {
  double r = 0.0;
  for (const auto& v : vertices) r = std::max(r, v.norm());
  return r;
}

ConvexPolygon make_box_polygon(double width, double height) {
  const double hx = 0.5 * width;
  const double hy = 0.5 * height;
  ConvexPolygon p;
  p.vertices = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  p.normals = {{0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}};
  return p;
}

}  // namespace impactbench::model::planar
