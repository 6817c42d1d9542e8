#pragma once
/// @file collide.h
/// Pure narrow-phase functions for every pair of shape kinds, and the jump table that
/// dispatches on (type of A, type of B). Every function returns a manifold whose normal
/// points from A to B and whose points carry depth and feature ids.
///
/// `margin` (metres, >= 0) makes contacts speculative: shapes up to `margin` apart still give
/// points, with negative depth (the gap), so the solver can stop them at the surface instead
/// of finding them a step later inside each other. With margin 0 only overlapping shapes give
/// points (touching at zero depth is no contact).

#include "core/manifold.h"
#include "core/shape.h"

namespace impulse2d {

/// Circle A vs circle B: touching iff (rA + rB)^2 > |pB - pA|^2. Coincident centres give the
/// fixed normal +y and depth rA + rB (the distance B must move to separate).
Manifold collide_circles(const Circle& a, const Transform& xa, const Circle& b, const Transform& xb,
                  float margin = 0.0f);

/// Axis-aligned box A vs axis-aligned box B: least-overlap axis, two points along the overlap.
Manifold collide_boxes(const Box& a, const Transform& xa, const Box& b, const Transform& xb,
                  float margin = 0.0f);

/// Axis-aligned box A vs circle B (handles a centre inside the box, non-square boxes).
Manifold collide_box_circle(const Box& a, const Transform& xa, const Circle& b, const Transform& xb,
                  float margin = 0.0f);

/// Convex polygon A vs circle B.
Manifold collide_polygon_circle(const Polygon& a, const Transform& xa, const Circle& b,
                                const Transform& xb,
                  float margin = 0.0f);

/// Convex polygon A vs convex polygon B by the separating axis test with reference/incident
/// face clipping.
Manifold collide_polygons(const Polygon& a, const Transform& xa, const Polygon& b, const Transform& xb,
                  float margin = 0.0f);

/// Axis-aligned box A vs polygon B (the box is treated as a 4-vertex polygon).
Manifold collide_box_polygon(const Box& a, const Transform& xa, const Polygon& b, const Transform& xb,
                  float margin = 0.0f);

/// Any two of box, polygon (rounded or not), capsule and segment: each is a convex outline grown
/// by a radius (a box's and a sharp polygon's 0, a capsule a 2-vertex outline with its radius,
/// a segment one with radius 0). Separating axis test on the outlines, reference/incident face
/// clipping with both radii in the depths, and, when the outlines are apart and nearest at a
/// corner, one point along the line between the nearest points (a circle's normal). Neither
/// shape may be a circle. The jump table keeps the older functions above for sharp polygons
/// and boxes, so this serves only pairs with a rounded polygon, capsule or segment in them.
Manifold collide_rounded(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb,
                         float margin = 0.0f);

/// A box, polygon (rounded or not), capsule or segment A vs circle B: the circle's centre
/// against A's bare outline, with both radii in the depth.
Manifold collide_rounded_circle(const Shape& a, const Transform& xa, const Circle& b,
                                const Transform& xb, float margin = 0.0f);

/// A chain link (a `Segment` with `one_sided`) A vs a circle, box, polygon or capsule B: the
/// segment's manifold, dropped for a shape behind the link and made smooth across the link's
/// joins with its neighbours (see collide_chain_link.cpp). Empty against a segment.
Manifold collide_chain_link(const Shape& link, const Transform& xa, const Shape& other,
                            const Transform& xb, float margin = 0.0f);

/// Signature of one entry of the collision jump table.
using CollideFunction = Manifold (*)(const Shape& a, const Transform& xa, const Shape& b,
                                     const Transform& xb, float margin);

/// The jump table entry for (type of A, type of B). The X-vs-Y and Y-vs-X entries differ only
/// in the order of the bodies (so the normal flips).
CollideFunction collide_function(ShapeType a, ShapeType b);

/// Dispatches through the jump table.
Manifold collide(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb,
                 float margin = 0.0f);

/// The polygon with the same outline as an axis-aligned box (4 vertices, CCW, starting at
/// the lower-left corner).
Polygon box_as_polygon(const Box& box);

}  // namespace impulse2d
