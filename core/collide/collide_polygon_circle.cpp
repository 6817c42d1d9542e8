/// @file collide_polygon_circle.cpp
/// Convex polygon vs circle.

#include "core/collide.h"
#include "core/collide/collide_internal.h"

#include <cmath>

namespace impulse2d {

Manifold collide_polygon_circle(const Polygon& a, const Transform& xa, const Circle& b,
                                const Transform& xb, float margin) {
  Manifold manifold;
  const float radius = b.radius;
  // Work in the polygon's frame.
  const vec2 centre = xa.apply_inverse(xb.position);

  // The face the centre is furthest outside of (or least inside of).
  int face = 0;
  float separation = glm::dot(a.normals[0], centre - a.vertices[0]);
  for (int i = 1; i < a.count; ++i) {
    const float face_separation = glm::dot(a.normals[i], centre - a.vertices[i]);
    if (face_separation > separation) {
      separation = face_separation;
      face = i;
    }
  }
  // Strict test: a circle further from the polygon than the margin (or, with no margin, that
  // only touches it) makes no contact.
  const float reach = radius + margin;
  if (!(separation < reach)) return manifold;

  const vec2 start = a.vertices[face];
  const vec2 end = a.vertices[collide_detail::next_vertex(face, a.count)];
  vec2 normal = a.normals[face];
  vec2 surface_a = centre - separation * normal;  // projection of the centre on the face
  std::uint32_t feature_a = collide_detail::edge_feature(face);
  if (separation > 0.0f) {
    // Centre outside: in the region of the face's start vertex, its end vertex, or the face.
    const bool before_start = glm::dot(centre - start, end - start) <= 0.0f;
    const bool after_end = glm::dot(centre - end, start - end) <= 0.0f;
    if (before_start || after_end) {
      const vec2 vertex = before_start ? start : end;
      const vec2 offset = centre - vertex;
      const float distance_squared = length_squared(offset);
      if (!(reach * reach > distance_squared)) return manifold;
      // distance >= separation > 0, so the division is safe.
      normal = offset / std::sqrt(distance_squared);
      surface_a = vertex;
      feature_a = collide_detail::vertex_feature(
          before_start ? face : collide_detail::next_vertex(face, a.count));
    }
  }
  // Otherwise the centre is inside (or on) the polygon: push out through the face of greatest
  // separation, depth r - separation (>= r).

  const vec2 surface_b = centre - radius * normal;
  manifold.normal = xa.rotation.rotate(normal);
  manifold.point_count = 1;
  manifold.points[0].depth = radius - glm::dot(centre - surface_a, normal);
  manifold.points[0].point = xa.apply(0.5f * (surface_a + surface_b));
  manifold.points[0].feature_id = make_feature_id(feature_a, collide_detail::circle_feature);
  return manifold;
}

}  // namespace impulse2d
