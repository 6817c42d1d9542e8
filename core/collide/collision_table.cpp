/// @file collision_table.cpp
/// The narrow phase's jump table: one entry per (type of A, type of B).
///
/// Each pair of kinds has one collide function written for a fixed order; the entry for the
/// swapped order calls it with the shapes swapped and flips the result: the normal is negated,
/// the points and depths stay, and the two halves of each feature id are swapped so the high
/// half still names a feature of the first shape.
///
/// Fixed orders: a circle is always second; otherwise the kind earlier in `ShapeType` is first.
/// Pairs of circles, boxes and sharp polygons use the tutorial's functions; any pair with a
/// rounded polygon, a capsule or a segment goes through collide_rounded(_circle), and any pair
/// with a chain link (a one-sided segment) through collide_chain_link.

#include "core/collide.h"
#include "core/collide/collide_internal.h"
#include "core/error.h"

#include <string>

namespace impulse2d {

namespace {

/// The manifold of (B, A) from the manifold of (A, B).
Manifold flipped(Manifold manifold) {
  manifold.normal = -manifold.normal;
  for (int i = 0; i < manifold.point_count; ++i) {
    manifold.points[i].feature_id = collide_detail::swap_feature_id(manifold.points[i].feature_id);
  }
  return manifold;
}

Manifold circle_vs_circle(const Shape& a, const Transform& xa, const Shape& b,
                          const Transform& xb, float margin) {
  return collide_circles(a.circle(), xa, b.circle(), xb, margin);
}

Manifold circle_vs_box(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb, float margin) {
  return flipped(collide_box_circle(b.box(), xb, a.circle(), xa, margin));
}

bool is_rounded(const Polygon& polygon) { return polygon.rounding > 0.0f; }

Manifold circle_vs_polygon(const Shape& a, const Transform& xa, const Shape& b,
                           const Transform& xb, float margin) {
  if (is_rounded(b.polygon())) return flipped(collide_rounded_circle(b, xb, a.circle(), xa, margin));
  return flipped(collide_polygon_circle(b.polygon(), xb, a.circle(), xa, margin));
}

/// Circle A vs capsule or segment B.
Manifold circle_vs_rounded(const Shape& a, const Transform& xa, const Shape& b,
                           const Transform& xb, float margin) {
  return flipped(collide_rounded_circle(b, xb, a.circle(), xa, margin));
}

Manifold box_vs_circle(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb, float margin) {
  return collide_box_circle(a.box(), xa, b.circle(), xb, margin);
}

Manifold box_vs_box(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb, float margin) {
  return collide_boxes(a.box(), xa, b.box(), xb, margin);
}

Manifold box_vs_polygon(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb, float margin) {
  if (is_rounded(b.polygon())) return collide_rounded(a, xa, b, xb, margin);
  return collide_box_polygon(a.box(), xa, b.polygon(), xb, margin);
}

Manifold polygon_vs_circle(const Shape& a, const Transform& xa, const Shape& b,
                           const Transform& xb, float margin) {
  if (is_rounded(a.polygon())) return collide_rounded_circle(a, xa, b.circle(), xb, margin);
  return collide_polygon_circle(a.polygon(), xa, b.circle(), xb, margin);
}

Manifold polygon_vs_box(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb, float margin) {
  if (is_rounded(a.polygon())) return flipped(collide_rounded(b, xb, a, xa, margin));
  return flipped(collide_box_polygon(b.box(), xb, a.polygon(), xa, margin));
}

Manifold polygon_vs_polygon(const Shape& a, const Transform& xa, const Shape& b,
                            const Transform& xb, float margin) {
  if (is_rounded(a.polygon()) || is_rounded(b.polygon())) return collide_rounded(a, xa, b, xb, margin);
  return collide_polygons(a.polygon(), xa, b.polygon(), xb, margin);
}

/// Capsule or segment A vs circle B.
Manifold rounded_vs_circle(const Shape& a, const Transform& xa, const Shape& b,
                           const Transform& xb, float margin) {
  return collide_rounded_circle(a, xa, b.circle(), xb, margin);
}

/// A box, polygon, capsule or segment A vs a capsule or segment B, B's kind no earlier.
Manifold rounded_pair(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb,
                      float margin) {
  return collide_rounded(a, xa, b, xb, margin);
}

/// A capsule or segment A vs a box, polygon or capsule B of an earlier kind.
Manifold rounded_pair_flipped(const Shape& a, const Transform& xa, const Shape& b,
                              const Transform& xb, float margin) {
  return flipped(collide_rounded(b, xb, a, xa, margin));
}

/// Segment A (a chain link or a plain segment) vs any B.
Manifold segment_vs_any(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb,
                        float margin) {
  if (a.segment().one_sided) return collide_chain_link(a, xa, b, xb, margin);
  if (b.type() == ShapeType::Circle) return rounded_vs_circle(a, xa, b, xb, margin);
  if (b.type() == ShapeType::Segment) {
    if (b.segment().one_sided) return flipped(collide_chain_link(b, xb, a, xa, margin));
    return rounded_pair(a, xa, b, xb, margin);
  }
  return rounded_pair_flipped(a, xa, b, xb, margin);
}

/// Any A but a segment vs segment B (a chain link or a plain segment).
Manifold any_vs_segment(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb,
                        float margin) {
  if (b.segment().one_sided) return flipped(collide_chain_link(b, xb, a, xa, margin));
  if (a.type() == ShapeType::Circle) return circle_vs_rounded(a, xa, b, xb, margin);
  return rounded_pair(a, xa, b, xb, margin);
}

/// Rows: type of A; columns: type of B; in `ShapeType` order (circle, box, polygon, capsule,
/// segment).
constexpr CollideFunction collision_table[shape_type_count][shape_type_count] = {
    {circle_vs_circle, circle_vs_box, circle_vs_polygon, circle_vs_rounded, any_vs_segment},
    {box_vs_circle, box_vs_box, box_vs_polygon, rounded_pair, any_vs_segment},
    {polygon_vs_circle, polygon_vs_box, polygon_vs_polygon, rounded_pair, any_vs_segment},
    {rounded_vs_circle, rounded_pair_flipped, rounded_pair_flipped, rounded_pair, any_vs_segment},
    {segment_vs_any, segment_vs_any, segment_vs_any, segment_vs_any, segment_vs_any},
};

int table_index(ShapeType type, const char* argument) {
  const int index = static_cast<int>(type);
  if (index < 0 || index >= shape_type_count) {
    throw Error(std::string("collide_function: ") + argument + " has unknown shape type " +
                std::to_string(index));
  }
  return index;
}

}  // namespace

CollideFunction collide_function(ShapeType a, ShapeType b) {
  return collision_table[table_index(a, "a")][table_index(b, "b")];
}

Manifold collide(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb,
                 float margin) {
  return collide_function(a.type(), b.type())(a, xa, b, xb, margin);
}

}  // namespace impulse2d
