/// @file collide_box_polygon.cpp
/// Axis-aligned box vs convex polygon: the box becomes a 4-vertex polygon.

#include "core/collide.h"
#include "core/collide/collide_internal.h"

namespace impulse2d {

Polygon box_as_polygon(const Box& box) {
  const vec2 extents = box.half_extents;
  Polygon polygon;
  polygon.count = 4;
  polygon.vertices[0] = vec2(-extents.x, -extents.y);
  polygon.vertices[1] = vec2(extents.x, -extents.y);
  polygon.vertices[2] = vec2(extents.x, extents.y);
  polygon.vertices[3] = vec2(-extents.x, extents.y);
  polygon.normals[0] = vec2(0.0f, -1.0f);
  polygon.normals[1] = vec2(1.0f, 0.0f);
  polygon.normals[2] = vec2(0.0f, 1.0f);
  polygon.normals[3] = vec2(-1.0f, 0.0f);
  return polygon;
}

Manifold collide_box_polygon(const Box& a, const Transform& xa, const Polygon& b,
                             const Transform& xb, float margin) {
  return collide_polygons(box_as_polygon(a), collide_detail::box_transform(xa), b, xb, margin);
}

}  // namespace impulse2d
