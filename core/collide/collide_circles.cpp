/// @file collide_circles.cpp
/// Circle vs circle.

#include "core/collide.h"
#include "core/collide/collide_internal.h"

#include <cmath>

namespace impulse2d {

Manifold collide_circles(const Circle& a, const Transform& xa, const Circle& b,
                         const Transform& xb, float margin) {
  Manifold manifold;
  const vec2 offset = xb.position - xa.position;
  const float distance_squared = length_squared(offset);
  const float radius_sum = a.radius + b.radius;
  // Strict test: circles further apart than the margin (or, with no margin, that only
  // touch) make no contact.
  const float reach = radius_sum + margin;
  if (!(reach * reach > distance_squared)) return manifold;

  // Coincident centres (or a distance so small its square underflows): fixed normal +y, and
  // the depth is how far B must move along it to separate.
  const float distance = std::sqrt(distance_squared);
  const bool coincident = !(distance > 0.0f);
  manifold.normal = coincident ? vec2(0.0f, 1.0f) : offset / distance;
  const float depth = coincident ? radius_sum : radius_sum - distance;

  const vec2 surface_a = xa.position + a.radius * manifold.normal;
  const vec2 surface_b = xb.position - b.radius * manifold.normal;
  manifold.point_count = 1;
  manifold.points[0].point = 0.5f * (surface_a + surface_b);
  manifold.points[0].depth = depth;
  manifold.points[0].feature_id =
      make_feature_id(collide_detail::circle_feature, collide_detail::circle_feature);
  return manifold;
}

}  // namespace impulse2d
