/// @file collide_boxes.cpp
/// Axis-aligned box vs axis-aligned box.

#include "core/collide.h"
#include "core/collide/collide_internal.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace impulse2d {

namespace {

/// Corner indices (numbered like `box_as_polygon`) at the lower and upper end of the face of a
/// box whose outward normal lies along `axis` (0 = x, 1 = y) with sign `positive`. The "lower"
/// end is the one with the smaller coordinate on the other axis.
struct FaceCorners {
  int lower;
  int upper;
};

FaceCorners face_corners(int axis, bool positive) {
  if (axis == 0) return positive ? FaceCorners{1, 2} : FaceCorners{0, 3};
  return positive ? FaceCorners{3, 2} : FaceCorners{0, 1};
}

}  // namespace

Manifold collide_boxes(const Box& a, const Transform& xa, const Box& b, const Transform& xb,
                       float margin) {
  Manifold manifold;
  const vec2 offset = xb.position - xa.position;
  // Penetration along each axis: how far B must move along it to separate.
  const vec2 overlap = a.half_extents + b.half_extents - glm::abs(offset);
  // Strict test: boxes further apart than the margin (or, with no margin, that only touch)
  // make no contact.
  if (!(overlap.x > -margin && overlap.y > -margin)) return manifold;

  // Resolve along the axis of least overlap (a gap is a negative overlap, so a separated pair
  // resolves along the axis that separates it); ties go to y (the usual resting case).
  const int axis = overlap.x < overlap.y ? 0 : 1;
  const int tangent_axis = 1 - axis;
  // Boxes apart on both axes (corner towards corner) have no faces facing each other. Apart
  // along the normal, faces that overlap by less than a centimetre along the tangent are a
  // corner grazing a corner (a box sliding along a floor made of boxes meets the next one's
  // side): no speculative contact there, or it would stop the slide at the seam.
  constexpr float graze_overlap = 0.01f;  // metres
  const float needed_face_overlap = overlap[axis] > 0.0f ? 0.0f : graze_overlap;
  if (!(overlap[tangent_axis] > needed_face_overlap)) return manifold;
  const bool positive = offset[axis] >= 0.0f;
  const float sign = positive ? 1.0f : -1.0f;
  manifold.normal[axis] = sign;

  // The faces that touch, and the overlap of their extents along the tangent axis.
  const float face_a = xa.position[axis] + sign * a.half_extents[axis];
  const float face_b = xb.position[axis] - sign * b.half_extents[axis];
  const float middle = 0.5f * (face_a + face_b);
  const float depth = overlap[axis];
  const float lower = std::max(xa.position[tangent_axis] - a.half_extents[tangent_axis],
                               xb.position[tangent_axis] - b.half_extents[tangent_axis]);
  const float upper = std::min(xa.position[tangent_axis] + a.half_extents[tangent_axis],
                               xb.position[tangent_axis] + b.half_extents[tangent_axis]);

  // Each end of the contact segment is named by the corners of A and B at that end.
  const FaceCorners corners_a = face_corners(axis, positive);
  const FaceCorners corners_b = face_corners(axis, !positive);
  const float ends[2] = {lower, upper};
  const int ends_a[2] = {corners_a.lower, corners_a.upper};
  const int ends_b[2] = {corners_b.lower, corners_b.upper};
  for (int end = 0; end < 2; ++end) {
    ManifoldPoint& point = manifold.points[end];
    point.point[axis] = middle;
    point.point[tangent_axis] = ends[end];
    point.depth = depth;
    point.feature_id = make_feature_id(collide_detail::vertex_feature(ends_a[end]),
                                       collide_detail::vertex_feature(ends_b[end]));
  }
  manifold.point_count = 2;
  return manifold;
}

}  // namespace impulse2d
