/// @file test_collide.cpp
/// Narrow phase: hand-placed cases for every pair of shape kinds in both orders, each of
/// PHYSICS.md's published-snippet mistakes, feature id stability and the jump table.

#include "core/collide.h"
#include "core/collide/collide_internal.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <vector>

namespace impulse2d {
namespace {

using collide_detail::circle_feature;
using collide_detail::edge_feature;
using collide_detail::vertex_feature;

/// Absolute tolerance for results of a handful of float operations on values of size `scale`:
/// 16 float epsilons relative, well above the few roundings involved, far below any mistake.
float tolerance(float scale = 1.0f) { return 16.0f * FLT_EPSILON * scale; }

constexpr float pi = 3.14159265358979323846f;

Transform at(vec2 position, float angle = 0.0f) { return {position, Rotation::from_angle(angle)}; }

void expect_vec_near(vec2 actual, vec2 expected, float abs_error) {
  EXPECT_NEAR(actual.x, expected.x, abs_error);
  EXPECT_NEAR(actual.y, expected.y, abs_error);
}

/// The point of `manifold` with `feature_id`, or null.
const ManifoldPoint* find_point(const Manifold& manifold, std::uint32_t feature_id) {
  for (int i = 0; i < manifold.point_count; ++i) {
    if (manifold.points[i].feature_id == feature_id) return &manifold.points[i];
  }
  return nullptr;
}

/// Expects a point with `feature_id` at `position` with `depth`.
void expect_point(const Manifold& manifold, std::uint32_t feature_id, vec2 position, float depth,
                  float abs_error) {
  const ManifoldPoint* point = find_point(manifold, feature_id);
  ASSERT_NE(point, nullptr) << "no point with feature id 0x" << std::hex << feature_id;
  expect_vec_near(point->point, position, abs_error);
  EXPECT_NEAR(point->depth, depth, abs_error);
}

/// Expects `swapped` (B vs A) to be `manifold` (A vs B) seen from the other side: opposite
/// normal, the same points and depths, feature ids with their halves swapped.
void expect_swapped(const Manifold& manifold, const Manifold& swapped, float abs_error) {
  ASSERT_EQ(swapped.point_count, manifold.point_count);
  expect_vec_near(swapped.normal, -manifold.normal, abs_error);
  for (int i = 0; i < manifold.point_count; ++i) {
    const ManifoldPoint& point = manifold.points[i];
    const ManifoldPoint* other =
        find_point(swapped, collide_detail::swap_feature_id(point.feature_id));
    ASSERT_NE(other, nullptr) << "point " << i << " missing from the swapped manifold";
    expect_vec_near(other->point, point.point, abs_error);
    EXPECT_NEAR(other->depth, point.depth, abs_error);
  }
}

void expect_unit(vec2 normal) { EXPECT_NEAR(glm::length(normal), 1.0f, tolerance()); }

// ---- circle vs circle ------------------------------------------------------------------

TEST(CollideCircles, OverlapAlongX) {
  const Manifold manifold =
      collide_circles(Circle{1.0f}, at({0.0f, 0.0f}), Circle{0.5f}, at({1.25f, 0.0f}));
  ASSERT_EQ(manifold.point_count, 1);
  EXPECT_EQ(manifold.normal, vec2(1.0f, 0.0f));
  // Surfaces at x = 1 (A) and x = 0.75 (B): midpoint 0.875, depth 0.25.
  expect_point(manifold, make_feature_id(circle_feature, circle_feature), {0.875f, 0.0f}, 0.25f,
               tolerance());
}

TEST(CollideCircles, DiagonalNormalIsUnit) {
  const Manifold manifold =
      collide_circles(Circle{1.0f}, at({0.0f, 0.0f}), Circle{1.0f}, at({0.6f, 0.8f}));
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {0.6f, 0.8f}, tolerance());
  expect_unit(manifold.normal);
  EXPECT_NEAR(manifold.points[0].depth, 1.0f, tolerance());
  expect_vec_near(manifold.points[0].point, {0.3f, 0.4f}, tolerance());
}

TEST(CollideCircles, SeparatedAndTouchingMakeNoContact) {
  // Mistake 1 (inverted test `r < dist`) would report these and miss overlapping ones.
  EXPECT_EQ(
      collide_circles(Circle{1.0f}, at({0.0f, 0.0f}), Circle{1.0f}, at({5.0f, 0.0f})).point_count,
      0);
  // Exactly touching (distance 1.5 = 1 + 0.5): zero depth is not a contact.
  EXPECT_EQ(
      collide_circles(Circle{1.0f}, at({0.0f, 0.0f}), Circle{0.5f}, at({1.5f, 0.0f})).point_count,
      0);
}

TEST(CollideCircles, DepthUsesRadiiNotTheirSquares) {
  // Mistake 2: with radii 2 the squared radius would give depth 4 + 4 - 3 = 5, not 1.
  const Manifold manifold =
      collide_circles(Circle{2.0f}, at({0.0f, 0.0f}), Circle{2.0f}, at({0.0f, 3.0f}));
  ASSERT_EQ(manifold.point_count, 1);
  EXPECT_FLOAT_EQ(manifold.points[0].depth, 1.0f);
  EXPECT_EQ(manifold.normal, vec2(0.0f, 1.0f));
}

TEST(CollideCircles, CoincidentCentresGiveFixedNormal) {
  const Manifold manifold =
      collide_circles(Circle{1.0f}, at({2.0f, 3.0f}), Circle{0.5f}, at({2.0f, 3.0f}));
  ASSERT_EQ(manifold.point_count, 1);
  EXPECT_EQ(manifold.normal, vec2(0.0f, 1.0f));
  EXPECT_FLOAT_EQ(manifold.points[0].depth, 1.5f);
  // Surfaces along +y: A's at y = 4, B's at y = 2.5.
  expect_vec_near(manifold.points[0].point, {2.0f, 3.25f}, tolerance(4.0f));
  EXPECT_TRUE(is_finite(manifold.points[0].point));
}

TEST(CollideCircles, SwappedOrderFlipsNormal) {
  const Manifold manifold =
      collide_circles(Circle{1.0f}, at({0.0f, 0.0f}), Circle{0.5f}, at({1.0f, 0.5f}));
  const Manifold swapped =
      collide_circles(Circle{0.5f}, at({1.0f, 0.5f}), Circle{1.0f}, at({0.0f, 0.0f}));
  ASSERT_EQ(manifold.point_count, 1);
  expect_swapped(manifold, swapped, tolerance(2.0f));
}

// ---- box vs box ------------------------------------------------------------------------

TEST(CollideBoxes, BoxRestingOnBoxHasTwoPoints) {
  // Ground 4 x 1 at the origin; a 1 x 1 box sunk 0.125 into it.
  const Manifold manifold =
      collide_boxes(Box{{2.0f, 0.5f}}, at({0.0f, 0.0f}), Box{{0.5f, 0.5f}}, at({0.25f, 0.875f}));
  // Mistake 9: the second point must not be dropped.
  ASSERT_EQ(manifold.point_count, 2);
  EXPECT_EQ(manifold.normal, vec2(0.0f, 1.0f));
  // Faces at y = 0.5 (A) and 0.375 (B); the overlap of the faces spans x in [-0.25, 0.75].
  expect_point(manifold, make_feature_id(vertex_feature(3), vertex_feature(0)), {-0.25f, 0.4375f},
               0.125f, 0.0f);
  expect_point(manifold, make_feature_id(vertex_feature(2), vertex_feature(1)), {0.75f, 0.4375f},
               0.125f, 0.0f);
}

TEST(CollideBoxes, LeastOverlapAxisAndNonZeroNormal) {
  // Mistake 3: overlap 0.125 along x, 1.5 along y. The greatest-overlap axis would be y; the
  // published snippet also left the normal zero.
  const Manifold manifold =
      collide_boxes(Box{{1.0f, 1.0f}}, at({0.0f, 0.0f}), Box{{1.0f, 1.0f}}, at({1.875f, 0.5f}));
  ASSERT_EQ(manifold.point_count, 2);
  EXPECT_EQ(manifold.normal, vec2(1.0f, 0.0f));
  // Faces at x = 1 (A) and 0.875 (B); y overlap [-0.5, 1].
  expect_point(manifold, make_feature_id(vertex_feature(1), vertex_feature(0)), {0.9375f, -0.5f},
               0.125f, 0.0f);
  expect_point(manifold, make_feature_id(vertex_feature(2), vertex_feature(3)), {0.9375f, 1.0f},
               0.125f, 0.0f);
}

TEST(CollideBoxes, NegativeDirections) {
  const Manifold left =
      collide_boxes(Box{{1.0f, 1.0f}}, at({0.0f, 0.0f}), Box{{1.0f, 1.0f}}, at({-1.875f, -0.5f}));
  ASSERT_EQ(left.point_count, 2);
  EXPECT_EQ(left.normal, vec2(-1.0f, 0.0f));
  expect_point(left, make_feature_id(vertex_feature(0), vertex_feature(1)), {-0.9375f, -1.0f},
               0.125f, 0.0f);
  expect_point(left, make_feature_id(vertex_feature(3), vertex_feature(2)), {-0.9375f, 0.5f},
               0.125f, 0.0f);

  const Manifold below =
      collide_boxes(Box{{1.0f, 1.0f}}, at({0.0f, 0.0f}), Box{{0.5f, 0.5f}}, at({0.0f, -1.25f}));
  ASSERT_EQ(below.point_count, 2);
  EXPECT_EQ(below.normal, vec2(0.0f, -1.0f));
  expect_point(below, make_feature_id(vertex_feature(0), vertex_feature(3)), {-0.5f, -0.875f},
               0.25f, 0.0f);
  expect_point(below, make_feature_id(vertex_feature(1), vertex_feature(2)), {0.5f, -0.875f}, 0.25f,
               0.0f);
}

TEST(CollideBoxes, SeparatedAndTouchingMakeNoContact) {
  EXPECT_EQ(collide_boxes(Box{{1.0f, 1.0f}}, at({0.0f, 0.0f}), Box{{1.0f, 1.0f}}, at({2.5f, 0.0f}))
                .point_count,
            0);
  EXPECT_EQ(collide_boxes(Box{{1.0f, 1.0f}}, at({0.0f, 0.0f}), Box{{1.0f, 1.0f}}, at({2.0f, 0.5f}))
                .point_count,
            0);
  // Overlapping along x only.
  EXPECT_EQ(collide_boxes(Box{{1.0f, 1.0f}}, at({0.0f, 0.0f}), Box{{1.0f, 1.0f}}, at({0.5f, 3.0f}))
                .point_count,
            0);
}

TEST(CollideBoxes, CoincidentBoxesPushAlongPlusY) {
  const Manifold manifold =
      collide_boxes(Box{{2.0f, 1.0f}}, at({0.0f, 0.0f}), Box{{2.0f, 1.0f}}, at({0.0f, 0.0f}));
  ASSERT_EQ(manifold.point_count, 2);
  EXPECT_EQ(manifold.normal, vec2(0.0f, 1.0f));
  EXPECT_EQ(manifold.points[0].depth, 2.0f);
  EXPECT_EQ(manifold.points[1].depth, 2.0f);
}

TEST(CollideBoxes, SwappedOrderFlipsNormalAndIgnoresRotation) {
  const Box ground{{2.0f, 0.5f}};
  const Box crate{{0.5f, 0.5f}};
  const Manifold manifold = collide_boxes(ground, at({0.0f, 0.0f}), crate, at({0.25f, 0.875f}));
  expect_swapped(manifold, collide_boxes(crate, at({0.25f, 0.875f}), ground, at({0.0f, 0.0f})),
                 0.0f);
  // A box never rotates: the rotation in its transform is ignored.
  const Manifold turned =
      collide_boxes(ground, at({0.0f, 0.0f}, 0.3f), crate, at({0.25f, 0.875f}, -1.0f));
  ASSERT_EQ(turned.point_count, 2);
  EXPECT_EQ(turned.normal, manifold.normal);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(turned.points[i].point, manifold.points[i].point);
    EXPECT_EQ(turned.points[i].feature_id, manifold.points[i].feature_id);
  }
}

// ---- box vs circle ---------------------------------------------------------------------

TEST(CollideBoxCircle, FaceRegion) {
  const Manifold manifold =
      collide_box_circle(Box{{2.0f, 1.0f}}, at({0.0f, 0.0f}), Circle{0.5f}, at({0.5f, 1.25f}));
  ASSERT_EQ(manifold.point_count, 1);
  EXPECT_EQ(manifold.normal, vec2(0.0f, 1.0f));
  // Box surface at y = 1, circle's lowest point at y = 0.75.
  expect_point(manifold, make_feature_id(edge_feature(2), circle_feature), {0.5f, 0.875f}, 0.25f,
               0.0f);
}

TEST(CollideBoxCircle, CornerRegionNormalIsNormalised) {
  // Mistake 4: the normal must be unit. Centre 0.5 from corner (2, 1) along (0.6, 0.8).
  const Manifold manifold =
      collide_box_circle(Box{{2.0f, 1.0f}}, at({0.0f, 0.0f}), Circle{1.0f}, at({2.3f, 1.4f}));
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {0.6f, 0.8f}, tolerance());
  expect_unit(manifold.normal);
  // Box surface at the corner (2, 1); circle's nearest point (1.7, 0.6).
  expect_point(manifold, make_feature_id(vertex_feature(2), circle_feature), {1.85f, 0.8f}, 0.5f,
               tolerance(2.0f));
}

TEST(CollideBoxCircle, CentreInsideNonSquareBoxPicksNearestFace) {
  // Mistake 4: centre (1, 0.5) inside a 8 x 2 box. Comparing |x| > |y| (right only for squares)
  // would push out through the right face, 3 away; the top face is 0.5 away.
  const Manifold manifold =
      collide_box_circle(Box{{4.0f, 1.0f}}, at({0.0f, 0.0f}), Circle{0.25f}, at({1.0f, 0.5f}));
  ASSERT_EQ(manifold.point_count, 1);
  EXPECT_EQ(manifold.normal, vec2(0.0f, 1.0f));
  // Depth r + distance to the face (positive: mistake 4's wrong sign would make it r - 0.5 < 0).
  // Surfaces: box top at y = 1; circle's point furthest against the normal at y = 0.25.
  expect_point(manifold, make_feature_id(edge_feature(2), circle_feature), {1.0f, 0.625f}, 0.75f,
               0.0f);

  // Below the centre line and nearer the left face of a tall box.
  const Manifold left =
      collide_box_circle(Box{{1.0f, 4.0f}}, at({0.0f, 0.0f}), Circle{0.25f}, at({-0.75f, -1.0f}));
  ASSERT_EQ(left.point_count, 1);
  EXPECT_EQ(left.normal, vec2(-1.0f, 0.0f));
  expect_point(left, make_feature_id(edge_feature(3), circle_feature), {-0.75f, -1.0f}, 0.5f, 0.0f);
}

TEST(CollideBoxCircle, CentreAtBoxCentreOrOnFaceStaysFinite) {
  // dist == 0 guards: the centre on the box centre, then exactly on the top face.
  const Manifold centred =
      collide_box_circle(Box{{4.0f, 1.0f}}, at({0.0f, 0.0f}), Circle{0.5f}, at({0.0f, 0.0f}));
  ASSERT_EQ(centred.point_count, 1);
  EXPECT_EQ(centred.normal, vec2(0.0f, 1.0f));
  EXPECT_EQ(centred.points[0].depth, 1.5f);
  EXPECT_TRUE(is_finite(centred.points[0].point));

  const Manifold on_face =
      collide_box_circle(Box{{2.0f, 1.0f}}, at({0.0f, 0.0f}), Circle{0.5f}, at({0.5f, 1.0f}));
  ASSERT_EQ(on_face.point_count, 1);
  EXPECT_EQ(on_face.normal, vec2(0.0f, 1.0f));
  expect_point(on_face, make_feature_id(edge_feature(2), circle_feature), {0.5f, 0.75f}, 0.5f,
               0.0f);
}

TEST(CollideBoxCircle, SeparatedAndTouchingMakeNoContact) {
  EXPECT_EQ(collide_box_circle(Box{{2.0f, 1.0f}}, at({0.0f, 0.0f}), Circle{0.5f}, at({0.0f, 2.0f}))
                .point_count,
            0);
  EXPECT_EQ(collide_box_circle(Box{{2.0f, 1.0f}}, at({0.0f, 0.0f}), Circle{0.5f}, at({0.0f, 1.5f}))
                .point_count,
            0);
  // Near a corner: inside both face slabs' reach but 0.5 from the corner with radius 0.45.
  EXPECT_EQ(collide_box_circle(Box{{2.0f, 1.0f}}, at({0.0f, 0.0f}), Circle{0.45f}, at({2.3f, 1.4f}))
                .point_count,
            0);
}

TEST(CollideBoxCircle, SwappedOrderViaTableAndRotationIgnored) {
  const Shape box = make_box({2.0f, 1.0f});
  const Shape circle = make_circle(1.0f);
  const Transform box_at = at({0.0f, 0.0f}, 0.4f);  // the box ignores this rotation
  const Transform circle_at = at({2.3f, 1.4f});
  const Manifold manifold = collide(box, box_at, circle, circle_at);
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {0.6f, 0.8f}, tolerance());
  expect_swapped(manifold, collide(circle, circle_at, box, box_at), 0.0f);
  EXPECT_EQ(collide(circle, circle_at, box, box_at).points[0].feature_id,
            make_feature_id(circle_feature, vertex_feature(2)));
}

// ---- polygon vs circle -----------------------------------------------------------------

/// The triangle (0,0), (2,0), (0,2) placed so its world vertices are exactly those points
/// (up to rounding of the centroid).
struct Triangle {
  Shape shape;
  Transform transform;
};

Triangle right_triangle() {
  const vec2 vertices[3] = {{0, 0}, {2, 0}, {0, 2}};
  vec2 centroid;
  Triangle triangle;
  triangle.shape = make_polygon(vertices, 3, &centroid);
  triangle.transform = at(centroid);
  return triangle;
}

TEST(CollidePolygonCircle, FaceRegion) {
  const Triangle triangle = right_triangle();
  const Manifold manifold = collide_polygon_circle(triangle.shape.polygon(), triangle.transform,
                                                   Circle{0.5f}, at({1.0f, -0.25f}));
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {0.0f, -1.0f}, tolerance());
  expect_point(manifold, make_feature_id(edge_feature(0), circle_feature), {1.0f, 0.125f}, 0.25f,
               tolerance(2.0f));
}

TEST(CollidePolygonCircle, VertexRegion) {
  const Triangle triangle = right_triangle();
  // 0.5 from vertex 1 (2, 0) along (0.6, -0.8).
  const Manifold manifold = collide_polygon_circle(triangle.shape.polygon(), triangle.transform,
                                                   Circle{1.0f}, at({2.3f, -0.4f}));
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {0.6f, -0.8f}, tolerance(2.0f));
  expect_unit(manifold.normal);
  expect_point(manifold, make_feature_id(vertex_feature(1), circle_feature), {1.85f, 0.2f}, 0.5f,
               tolerance(4.0f));
  // Same centre, radius 0.45: the bottom face is only 0.4 away, but the vertex is 0.5 away.
  EXPECT_EQ(collide_polygon_circle(triangle.shape.polygon(), triangle.transform, Circle{0.45f},
                                   at({2.3f, -0.4f}))
                .point_count,
            0);
}

TEST(CollidePolygonCircle, CentreInside) {
  const Triangle triangle = right_triangle();
  // Centre (0.5, 0.25): 0.25 above the bottom face, further from the others.
  const Manifold manifold = collide_polygon_circle(triangle.shape.polygon(), triangle.transform,
                                                   Circle{0.25f}, at({0.5f, 0.25f}));
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {0.0f, -1.0f}, tolerance());
  // Depth r + 0.25 (distance to push out); surfaces at y = 0 (face) and y = 0.5 (circle top).
  expect_point(manifold, make_feature_id(edge_feature(0), circle_feature), {0.5f, 0.25f}, 0.5f,
               tolerance(2.0f));
}

TEST(CollidePolygonCircle, TurnedPolygonVertexRegion) {
  // A 2 x 2 square turned 45 degrees: its top vertex is at (0, sqrt 2).
  const Shape diamond = make_oriented_box({1.0f, 1.0f});
  const float top = std::sqrt(2.0f);
  const Manifold manifold = collide_polygon_circle(diamond.polygon(), at({0.0f, 0.0f}, 0.25f * pi),
                                                   Circle{0.5f}, at({0.0f, top + 0.25f}));
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {0.0f, 1.0f}, tolerance(2.0f));
  EXPECT_NEAR(manifold.points[0].depth, 0.25f, tolerance(2.0f));
  expect_vec_near(manifold.points[0].point, {0.0f, top - 0.125f}, tolerance(2.0f));
}

TEST(CollidePolygonCircle, SeparatedAndTouchingMakeNoContact) {
  const Triangle triangle = right_triangle();
  EXPECT_EQ(collide_polygon_circle(triangle.shape.polygon(), triangle.transform, Circle{0.5f},
                                   at({1.0f, -1.0f}))
                .point_count,
            0);
  EXPECT_EQ(collide_polygon_circle(triangle.shape.polygon(), triangle.transform, Circle{0.5f},
                                   at({-1.0f, 1.0f}))
                .point_count,
            0);
  EXPECT_EQ(collide_polygon_circle(triangle.shape.polygon(), triangle.transform, Circle{0.5f},
                                   at({3.0f, 3.0f}))
                .point_count,
            0);
}

TEST(CollidePolygonCircle, SwappedOrderViaTable) {
  const Triangle triangle = right_triangle();
  const Shape circle = make_circle(1.0f);
  const Manifold manifold = collide(triangle.shape, triangle.transform, circle, at({2.3f, -0.4f}));
  ASSERT_EQ(manifold.point_count, 1);
  expect_swapped(manifold, collide(circle, at({2.3f, -0.4f}), triangle.shape, triangle.transform),
                 0.0f);
}

// ---- polygon vs polygon ----------------------------------------------------------------

TEST(CollidePolygons, BoxRestingOnBoxHasTwoPointsOfEqualDepth) {
  const Shape ground = make_oriented_box({2.0f, 0.5f});
  const Shape crate = make_oriented_box({0.5f, 0.5f});
  const Manifold manifold = collide(ground, at({0.0f, 0.0f}), crate, at({0.25f, 0.875f}));
  ASSERT_EQ(manifold.point_count, 2);
  EXPECT_EQ(manifold.normal, vec2(0.0f, 1.0f));
  EXPECT_EQ(manifold.points[0].depth, manifold.points[1].depth);
  // The same points and ids as the axis-aligned box test.
  expect_point(manifold, make_feature_id(vertex_feature(3), vertex_feature(0)), {-0.25f, 0.4375f},
               0.125f, 0.0f);
  expect_point(manifold, make_feature_id(vertex_feature(2), vertex_feature(1)), {0.75f, 0.4375f},
               0.125f, 0.0f);
  expect_swapped(manifold, collide(crate, at({0.25f, 0.875f}), ground, at({0.0f, 0.0f})), 0.0f);
}

TEST(CollidePolygons, EqualDepthsWhenTheWholeStackIsTurned) {
  // The same stack turned by 0.3 rad about the origin: both bodies share the angle, so the
  // crate's bottom stays exactly parallel to the ground's top in the ground's frame.
  const float angle = 0.3f;
  const Rotation turn = Rotation::from_angle(angle);
  const Shape ground = make_oriented_box({2.0f, 0.5f});
  const Shape crate = make_oriented_box({0.5f, 0.5f});
  const Manifold manifold =
      collide(ground, {{0.0f, 0.0f}, turn}, crate, {turn.rotate({0.25f, 0.875f}), turn});
  ASSERT_EQ(manifold.point_count, 2);
  EXPECT_EQ(manifold.points[0].depth, manifold.points[1].depth);
  expect_vec_near(manifold.normal, turn.rotate({0.0f, 1.0f}), tolerance());
  expect_point(manifold, make_feature_id(vertex_feature(3), vertex_feature(0)),
               turn.rotate({-0.25f, 0.4375f}), 0.125f, tolerance(2.0f));
  expect_point(manifold, make_feature_id(vertex_feature(2), vertex_feature(1)),
               turn.rotate({0.75f, 0.4375f}), 0.125f, tolerance(2.0f));
}

TEST(CollidePolygons, SlightlyTurnedCrate) {
  const Shape ground = make_oriented_box({2.0f, 0.5f});
  const Shape crate = make_oriented_box({0.5f, 0.5f});
  const float angle = 0.05f;
  for (float height : {0.9f, 0.99f}) {
    const Transform crate_at = at({0.0f, height}, angle);
    // Expected: each bottom corner below the ground's top (y = 0.5) is a point.
    const vec2 corners[2] = {crate_at.apply(crate.polygon().vertices[0]),
                             crate_at.apply(crate.polygon().vertices[1])};
    const Manifold manifold = collide(ground, at({0.0f, 0.0f}), crate, crate_at);
    EXPECT_EQ(manifold.normal, vec2(0.0f, 1.0f));
    int expected_count = 0;
    for (int corner = 0; corner < 2; ++corner) {
      const float depth = 0.5f - corners[corner].y;
      if (depth <= 0.0f) continue;
      ++expected_count;
      // Ground's top edge is 2 (vertex 2 -> 3); corner 1 lies at vertex 2's end, corner 0 at 3's.
      const std::uint32_t id = corner == 1 ? make_feature_id(vertex_feature(2), vertex_feature(1))
                                           : make_feature_id(vertex_feature(3), vertex_feature(0));
      expect_point(manifold, id, corners[corner] + vec2(0.0f, 0.5f * depth), depth, tolerance());
    }
    EXPECT_EQ(manifold.point_count, expected_count) << "height " << height;
  }
}

TEST(CollidePolygons, DiamondCornerIntoGround) {
  // A 1 x 1 square turned 45 degrees with its bottom vertex 0.1 into the ground.
  const Shape ground = make_oriented_box({2.0f, 0.5f});
  const Shape diamond = make_oriented_box({0.5f, 0.5f});
  const float half_diagonal = std::sqrt(0.5f);
  const Manifold manifold =
      collide(ground, at({0.0f, 0.0f}), diamond, at({0.0f, 0.4f + half_diagonal}, 0.25f * pi));
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {0.0f, 1.0f}, tolerance());
  EXPECT_NEAR(manifold.points[0].depth, 0.1f, tolerance());
  expect_vec_near(manifold.points[0].point, {0.0f, 0.45f}, tolerance());
}

TEST(CollidePolygons, ReferenceFaceOnBWhenItSeparatesMore) {
  // The ground's corner pokes into the diamond's lower-left face: B's face gives the smallest
  // penetration, so B is the reference and the normal (A to B) is minus B's face normal.
  const Shape ground = make_oriented_box({1.0f, 1.0f});
  const Shape diamond = make_oriented_box({1.0f, 1.0f});
  // The diamond's face is 1 from its centre; the centre sits 0.875 from the corner (1, 1) along
  // the diagonal, so the corner is 0.125 inside that face.
  const float diagonal = std::sqrt(0.5f);
  const vec2 centre = vec2(1.0f, 1.0f) + 0.875f * vec2(diagonal, diagonal);
  const Manifold manifold = collide(ground, at({0.0f, 0.0f}), diamond, at(centre, 0.25f * pi));
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {diagonal, diagonal}, tolerance(2.0f));
  EXPECT_NEAR(manifold.points[0].depth, 0.125f, tolerance(4.0f));
  // Midway between the corner and the diamond's face, 0.125 further towards A.
  expect_vec_near(manifold.points[0].point, vec2(1.0f, 1.0f) - 0.0625f * vec2(diagonal, diagonal),
                  tolerance(4.0f));
}

TEST(CollidePolygons, SeparatedAndTouchingMakeNoContact) {
  const Shape ground = make_oriented_box({2.0f, 0.5f});
  const Shape crate = make_oriented_box({0.5f, 0.5f});
  EXPECT_EQ(collide(ground, at({0.0f, 0.0f}), crate, at({0.0f, 1.5f})).point_count, 0);
  EXPECT_EQ(collide(ground, at({0.0f, 0.0f}), crate, at({0.0f, 1.0f})).point_count, 0);  // touching
  EXPECT_EQ(collide(ground, at({0.0f, 0.0f}), crate, at({3.0f, 0.0f}, 0.3f)).point_count, 0);
}

TEST(CollidePolygons, FeatureIdsStableUnderTinyTranslation) {
  const Shape ground = make_oriented_box({2.0f, 0.5f});
  const Shape crate = make_oriented_box({0.5f, 0.5f});
  struct Case {
    vec2 position;
    float angle;
  };
  // Includes a crate exactly as wide as an edge end: (1.5, y) puts its right corners on the
  // ground's right side plane, so a tiny nudge moves an incident vertex across it.
  const Case cases[] = {{{0.25f, 0.875f}, 0.0f}, {{0.0f, 0.9f}, 0.05f}, {{1.5f, 0.875f}, 0.0f}};
  const vec2 nudges[] = {{1e-5f, 0.0f}, {-1e-5f, 0.0f}, {0.0f, -1e-5f}, {1e-5f, 1e-5f}};
  for (const Case& base : cases) {
    const Manifold reference =
        collide(ground, at({0.0f, 0.0f}), crate, at(base.position, base.angle));
    ASSERT_EQ(reference.point_count, 2);
    for (const vec2 nudge : nudges) {
      const Manifold moved =
          collide(ground, at({0.0f, 0.0f}), crate, at(base.position + nudge, base.angle));
      ASSERT_EQ(moved.point_count, 2);
      for (int i = 0; i < 2; ++i) {
        const ManifoldPoint* same = find_point(moved, reference.points[i].feature_id);
        ASSERT_NE(same, nullptr);
        expect_vec_near(same->point, reference.points[i].point, 2e-5f);
      }
    }
  }
}

TEST(CollideBoxes, FeatureIdsStableUnderTinyTranslation) {
  const Box ground{{2.0f, 0.5f}};
  const Box crate{{0.5f, 0.5f}};
  const Manifold reference = collide_boxes(ground, at({0.0f, 0.0f}), crate, at({1.5f, 0.875f}));
  for (const vec2 nudge : {vec2(1e-5f, 0.0f), vec2(-1e-5f, 0.0f), vec2(0.0f, 1e-5f)}) {
    const Manifold moved =
        collide_boxes(ground, at({0.0f, 0.0f}), crate, at(vec2(1.5f, 0.875f) + nudge));
    ASSERT_EQ(moved.point_count, 2);
    for (int i = 0; i < 2; ++i)
      EXPECT_EQ(moved.points[i].feature_id, reference.points[i].feature_id);
  }
}

// ---- box vs polygon --------------------------------------------------------------------

TEST(CollideBoxPolygon, MatchesBoxVsBoxAndFlips) {
  const Shape ground = make_box({2.0f, 0.5f});
  const Shape crate = make_oriented_box({0.5f, 0.5f});
  const Transform ground_at = at({0.0f, 0.0f}, 1.0f);  // ignored for the box
  const Manifold manifold = collide(ground, ground_at, crate, at({0.25f, 0.875f}));
  const Manifold boxes =
      collide_boxes(ground.box(), ground_at, Box{{0.5f, 0.5f}}, at({0.25f, 0.875f}));
  ASSERT_EQ(manifold.point_count, 2);
  EXPECT_EQ(manifold.normal, boxes.normal);
  for (int i = 0; i < 2; ++i) {
    expect_point(manifold, boxes.points[i].feature_id, boxes.points[i].point, boxes.points[i].depth,
                 0.0f);
  }
  expect_swapped(manifold, collide(crate, at({0.25f, 0.875f}), ground, ground_at), 0.0f);
}

TEST(CollideBoxPolygon, TriangleOnBox) {
  // The triangle's bottom edge 0.125 into the top of a 4 x 1 box.
  Triangle triangle = right_triangle();
  triangle.transform.position += vec2(-1.0f, 0.375f);
  const Manifold manifold =
      collide(make_box({2.0f, 0.5f}), at({0.0f, 0.0f}), triangle.shape, triangle.transform);
  ASSERT_EQ(manifold.point_count, 2);
  expect_vec_near(manifold.normal, {0.0f, 1.0f}, tolerance());
  expect_point(manifold, make_feature_id(vertex_feature(2), vertex_feature(1)), {1.0f, 0.4375f},
               0.125f, tolerance(2.0f));
  expect_point(manifold, make_feature_id(vertex_feature(3), vertex_feature(0)), {-1.0f, 0.4375f},
               0.125f, tolerance(2.0f));
}

TEST(CollideBoxPolygon, BoxAsPolygonIsCounterClockwiseFromLowerLeft) {
  const Polygon polygon = box_as_polygon(Box{{2.0f, 1.0f}});
  ASSERT_EQ(polygon.count, 4);
  EXPECT_EQ(polygon.vertices[0], vec2(-2.0f, -1.0f));
  EXPECT_EQ(polygon.vertices[1], vec2(2.0f, -1.0f));
  EXPECT_EQ(polygon.vertices[2], vec2(2.0f, 1.0f));
  EXPECT_EQ(polygon.vertices[3], vec2(-2.0f, 1.0f));
  for (int i = 0; i < 4; ++i) {
    const vec2 edge = polygon.vertices[(i + 1) % 4] - polygon.vertices[i];
    EXPECT_EQ(polygon.normals[i], glm::normalize(right_perpendicular(edge)));
  }
}

// ---- jump table ------------------------------------------------------------------------

/// One shape of each kind, placed so that every pair overlaps.
struct Placed {
  Shape shape;
  Transform transform;
};

std::vector<Placed> overlapping_shapes() {
  return {{make_circle(0.75f), at({0.0f, 0.0f})},
          {make_box({0.5f, 0.75f}), at({0.5f, 0.25f})},
          {make_oriented_box({0.5f, 0.25f}), at({-0.25f, 0.5f}, 0.4f)}};
}

TEST(CollisionTable, EveryPairBothOrders) {
  const std::vector<Placed> shapes = overlapping_shapes();
  for (const Placed& a : shapes) {
    for (const Placed& b : shapes) {
      ASSERT_NE(collide_function(a.shape.type(), b.shape.type()), nullptr);
      const Manifold manifold = collide(a.shape, a.transform, b.shape, b.transform);
      const Manifold swapped = collide(b.shape, b.transform, a.shape, a.transform);
      SCOPED_TRACE(testing::Message()
                   << "A type " << int(a.shape.type()) << ", B type " << int(b.shape.type()));
      ASSERT_GT(manifold.point_count, 0);
      expect_unit(manifold.normal);
      for (int i = 0; i < manifold.point_count; ++i) {
        EXPECT_GT(manifold.points[i].depth, 0.0f);
        EXPECT_TRUE(is_finite(manifold.points[i].point));
      }
      if (&a == &b) continue;  // a shape against itself is symmetric, not flipped
      expect_swapped(manifold, swapped, tolerance(2.0f));
      // Mixed kinds go through one function and a flip: bit-identical points.
      if (a.shape.type() != b.shape.type()) {
        for (int i = 0; i < manifold.point_count; ++i) {
          const ManifoldPoint* other =
              find_point(swapped, collide_detail::swap_feature_id(manifold.points[i].feature_id));
          ASSERT_NE(other, nullptr);
          EXPECT_EQ(other->point, manifold.points[i].point);
          EXPECT_EQ(other->depth, manifold.points[i].depth);
        }
        EXPECT_EQ(swapped.normal, -manifold.normal);
      }
    }
  }
}

TEST(CollisionTable, EveryPairSeparatedGivesNoPoints) {
  std::vector<Placed> shapes = overlapping_shapes();
  for (const Placed& a : shapes) {
    for (Placed b : shapes) {
      b.transform.position += vec2(10.0f, -7.0f);
      EXPECT_EQ(collide(a.shape, a.transform, b.shape, b.transform).point_count, 0);
      EXPECT_EQ(collide(b.shape, b.transform, a.shape, a.transform).point_count, 0);
    }
  }
}

TEST(CollisionTable, UnknownShapeTypeIsAnError) {
  EXPECT_THROW(collide_function(static_cast<ShapeType>(7), ShapeType::Circle), Error);
  EXPECT_THROW(collide_function(ShapeType::Box, static_cast<ShapeType>(3)), Error);
}

}  // namespace
}  // namespace impulse2d
