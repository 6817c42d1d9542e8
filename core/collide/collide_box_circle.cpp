/// @file collide_box_circle.cpp
/// Axis-aligned box vs circle.

#include "core/collide.h"
#include "core/collide/collide_internal.h"

#include <glm/common.hpp>

#include <cmath>

namespace impulse2d {

namespace {

/// Edge of a box (numbered like `box_as_polygon`) whose outward normal is along `axis`
/// (0 = x, 1 = y) with sign `positive`.
int box_edge(int axis, bool positive) {
  if (axis == 0) return positive ? 1 : 3;
  return positive ? 2 : 0;
}

/// Corner of a box (numbered like `box_as_polygon`) in the quadrant of `direction`.
int box_corner(vec2 direction) {
  if (direction.y < 0.0f) return direction.x < 0.0f ? 0 : 1;
  return direction.x < 0.0f ? 3 : 2;
}

}  // namespace

Manifold collide_box_circle(const Box& a, const Transform& xa, const Circle& b,
                            const Transform& xb, float margin) {
  Manifold manifold;
  const vec2 extents = a.half_extents;
  const float radius = b.radius;
  // Everything below is relative to the box centre; the box never rotates.
  const vec2 centre = xb.position - xa.position;
  const vec2 closest = glm::clamp(centre, -extents, extents);
  const vec2 outside_offset = centre - closest;
  const float distance_squared = length_squared(outside_offset);
  // Strict test: a circle further from the box than the margin (or, with no margin, that only
  // touches it) makes no contact.
  const float reach = radius + margin;
  if (!(reach * reach > distance_squared)) return manifold;

  vec2 normal{0.0f, 0.0f};
  vec2 surface_a{0.0f, 0.0f};  // the box's surface point, relative to its centre
  std::uint32_t feature_a = 0;
  if (distance_squared > 0.0f) {
    // Centre outside the box: the normal runs from the closest point to the centre.
    normal = outside_offset / std::sqrt(distance_squared);
    surface_a = closest;
    const bool clamped_x = closest.x != centre.x;
    const bool clamped_y = closest.y != centre.y;
    if (clamped_x && clamped_y) {
      feature_a = collide_detail::vertex_feature(box_corner(centre));
    } else {
      const int axis = clamped_x ? 0 : 1;
      feature_a = collide_detail::edge_feature(box_edge(axis, centre[axis] > 0.0f));
    }
  } else {
    // Centre inside (or on) the box: push out through the nearest face, found by the smallest
    // distance to a face per axis, which is right for boxes that are not square.
    const vec2 gap = extents - glm::abs(centre);
    const int axis = gap.x < gap.y ? 0 : 1;  // ties go to y
    const bool positive = centre[axis] >= 0.0f;
    const float sign = positive ? 1.0f : -1.0f;
    normal[axis] = sign;
    surface_a = centre;
    surface_a[axis] = sign * extents[axis];
    feature_a = collide_detail::edge_feature(box_edge(axis, positive));
  }

  const vec2 surface_b = centre - radius * normal;
  manifold.normal = normal;
  manifold.point_count = 1;
  // The depth is the circle's reach past the box surface along the normal: r - dist outside,
  // r + (distance to the face) inside.
  manifold.points[0].depth = radius - glm::dot(centre - surface_a, normal);
  manifold.points[0].point = xa.position + 0.5f * (surface_a + surface_b);
  manifold.points[0].feature_id = make_feature_id(feature_a, collide_detail::circle_feature);
  return manifold;
}

}  // namespace impulse2d
