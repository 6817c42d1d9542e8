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
  EXPECT_THROW(collide_function(ShapeType::Box, static_cast<ShapeType>(5)), Error);
}


// ---- capsules, segments, rounded polygons (issue 31) -------------------------------------

const vec2 pentagon[5] = {vec2{0.6f, -0.45f}, vec2{0.75f, 0.25f}, vec2{0.0f, 0.65f},
                          vec2{-0.75f, 0.25f}, vec2{-0.6f, -0.45f}};

/// One shape of every kind (the new ones twice: two capsules, two segments, two rounded
/// polygons, so same-kind pairs are tested too), placed so that every pair overlaps and no
/// same-kind pair is a near tie between the two reference faces.
std::vector<Placed> every_kind_overlapping() {
  return {{make_circle(0.75f), at({0.0f, 0.0f})},
          {make_box({0.5f, 0.75f}), at({0.5f, 0.25f})},
          {make_oriented_box({0.5f, 0.25f}), at({-0.25f, 0.5f}, 0.4f)},
          {make_polygon(pentagon, 5), at({0.1f, -0.3f}, -0.2f)},
          {make_rounded_polygon(pentagon, 5, 0.2f), at({0.2f, 0.1f}, 0.3f)},
          {make_rounded_polygon(pentagon, 5, 0.1f), at({-0.3f, -0.2f}, 1.1f)},
          {make_capsule({-0.8f, 0.0f}, {0.8f, 0.0f}, 0.3f), at({0.1f, 0.2f}, 0.15f)},
          {make_capsule({0.0f, -0.6f}, {0.0f, 0.6f}, 0.2f), at({0.1f, 0.0f}, -0.5f)},
          {make_segment({-1.5f, 0.0f}, {1.5f, 0.0f}), at({0.0f, 0.1f}, 0.05f)},
          {make_segment({-1.0f, 0.0f}, {1.0f, 0.0f}), at({0.2f, 0.1f}, 1.3f)}};
}

std::string describe(const Placed& placed) {
  const Shape& shape = placed.shape;
  std::string name = std::to_string(static_cast<int>(shape.type()));
  if (shape.type() == ShapeType::Polygon) name += " rounding " + std::to_string(shape.polygon().rounding);
  return name + " at (" + std::to_string(placed.transform.position.x) + ", " +
         std::to_string(placed.transform.position.y) + ")";
}

// Every pair among circle, box, oriented box, polygon, rounded polygon, capsule and segment, in
// both orders: at most two points, a unit normal, finite points, and, when the kinds differ,
// the two orders mirrored bit for bit (one function and a flip).
TEST(CollisionTable, EveryKindEveryPairBothOrdersMirrored) {
  const std::vector<Placed> shapes = every_kind_overlapping();
  for (const Placed& a : shapes) {
    for (const Placed& b : shapes) {
      if (&a == &b) continue;
      SCOPED_TRACE("A " + describe(a) + ", B " + describe(b));
      const Manifold manifold = collide(a.shape, a.transform, b.shape, b.transform, 0.02f);
      const Manifold swapped = collide(b.shape, b.transform, a.shape, a.transform, 0.02f);
      ASSERT_GT(manifold.point_count, 0);
      ASSERT_LE(manifold.point_count, max_manifold_points);
      expect_unit(manifold.normal);
      for (int i = 0; i < manifold.point_count; ++i) {
        EXPECT_TRUE(std::isfinite(manifold.points[i].depth));
        EXPECT_TRUE(is_finite(manifold.points[i].point));
      }
      ASSERT_GT(swapped.point_count, 0);
      // Two shapes of one kind go through one function in both orders; deep in each other, as
      // here, the two orders may pick different reference faces (a near tie, as for two
      // polygons today): the same-kind tests below mirror clear cases.
      if (a.shape.type() != b.shape.type()) {
        expect_swapped(manifold, swapped, tolerance(4.0f));
        EXPECT_EQ(swapped.normal, -manifold.normal);
        for (int i = 0; i < manifold.point_count; ++i) {
          const ManifoldPoint* other =
              find_point(swapped, collide_detail::swap_feature_id(manifold.points[i].feature_id));
          ASSERT_NE(other, nullptr);
          EXPECT_EQ(other->point, manifold.points[i].point);
          EXPECT_EQ(other->depth, manifold.points[i].depth);
        }
      }
    }
  }
}

TEST(CollisionTable, EveryKindSeparatedGivesNoPointsAndMarginGivesGaps) {
  const std::vector<Placed> shapes = every_kind_overlapping();
  for (const Placed& a : shapes) {
    for (Placed b : shapes) {
      b.transform.position += vec2(10.0f, -7.0f);
      EXPECT_EQ(collide(a.shape, a.transform, b.shape, b.transform, 0.05f).point_count, 0);
      EXPECT_EQ(collide(b.shape, b.transform, a.shape, a.transform, 0.05f).point_count, 0);
    }
  }
}

TEST(CollideCapsules, CrossingAtRightAnglesGiveOnePoint) {
  // A lying capsule (radius 0.25) and a standing one (radius 0.2) whose lower cap dips 1 cm
  // into it, off-centre.
  const Shape lying = make_capsule({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f);
  const Shape standing = make_capsule({0.0f, -0.5f}, {0.0f, 0.5f}, 0.2f);
  const Transform xb = at({0.3f, 0.25f + 0.2f + 0.5f - 0.01f});
  const Manifold manifold = collide(lying, at({0.0f, 0.0f}), standing, xb, 0.02f);
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {0.0f, 1.0f}, tolerance());
  EXPECT_NEAR(manifold.points[0].depth, 0.01f, tolerance());
  expect_vec_near(manifold.points[0].point, {0.3f, 0.25f - 0.005f}, tolerance());
  expect_swapped(manifold, collide(standing, xb, lying, at({0.0f, 0.0f}), 0.02f), tolerance());
}

TEST(CollideCapsules, ParallelGiveTwoPoints) {
  const Shape lower = make_capsule({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f);
  const Shape upper = make_capsule({-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f);
  const Transform xb = at({0.2f, 0.5f - 0.02f});
  const Manifold manifold = collide(lower, at({0.0f, 0.0f}), upper, xb, 0.02f);
  ASSERT_EQ(manifold.point_count, 2);
  expect_vec_near(manifold.normal, {0.0f, 1.0f}, tolerance());
  EXPECT_NE(manifold.points[0].feature_id, manifold.points[1].feature_id);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(manifold.points[i].depth, 0.02f, tolerance());
    EXPECT_NEAR(manifold.points[i].point.y, 0.25f - 0.01f, tolerance());
  }
  EXPECT_NEAR(std::fabs(manifold.points[0].point.x - manifold.points[1].point.x), 1.0f, tolerance());
}

TEST(CollideCapsules, EndToEndGivesTheCapsNormal) {
  // Two capsules on one line, caps 1 cm into each other: one point on the axis (no face normal
  // of either separates them: the corner case must find it).
  const Shape a = make_capsule({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f);
  const Shape b = make_capsule({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f);
  const Manifold manifold = collide(a, at({0.0f, 0.0f}), b, at({2.49f, 0.0f}), 0.0f);
  ASSERT_EQ(manifold.point_count, 1);
  expect_vec_near(manifold.normal, {1.0f, 0.0f}, tolerance());
  EXPECT_NEAR(manifold.points[0].depth, 0.01f, tolerance(4.0f));
  expect_vec_near(manifold.points[0].point, {1.245f, 0.0f}, tolerance(2.0f));
  // Turned a little about the touching caps: still one point, the normal between the caps.
  const Transform turned{vec2(1.0f + 0.49f * std::cos(0.2f), 0.49f * std::sin(0.2f)) +
                             Rotation::from_angle(0.3f).rotate(vec2(1.0f, 0.0f)),
                         Rotation::from_angle(0.3f)};
  const Manifold tilted = collide(a, at({0.0f, 0.0f}), b, turned, 0.0f);
  ASSERT_EQ(tilted.point_count, 1);
  expect_vec_near(tilted.normal, {std::cos(0.2f), std::sin(0.2f)}, 1e-5f);
  EXPECT_NEAR(tilted.points[0].depth, 0.01f, 1e-5f);
}

TEST(CollideCapsules, LyingOnBoxTwoPointsAtRestDepthZero) {
  const Shape ground = make_box({5.0f, 0.5f});
  const Shape capsule = make_capsule({-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f);
  // Capsule axis 0.25 m above the ground's top: touching, and with a 2 cm margin a contact.
  const Manifold manifold = collide(ground, at({0.0f, -0.5f}), capsule, at({0.0f, 0.25f}), 0.02f);
  ASSERT_EQ(manifold.point_count, 2);
  expect_vec_near(manifold.normal, {0.0f, 1.0f}, tolerance());
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(manifold.points[i].depth, 0.0f, tolerance());
  // 1 cm above: two speculative points of depth -0.01.
  const Manifold gap = collide(ground, at({0.0f, -0.5f}), capsule, at({0.0f, 0.26f}), 0.02f);
  ASSERT_EQ(gap.point_count, 2);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(gap.points[i].depth, -0.01f, tolerance());
  // 3 cm above: beyond the margin.
  EXPECT_EQ(collide(ground, at({0.0f, -0.5f}), capsule, at({0.0f, 0.28f}), 0.02f).point_count, 0);
}

TEST(CollideCapsules, FeatureIdsStableUnderTinyTranslation) {
  const Shape ground = make_box({5.0f, 0.5f});
  const Shape capsule = make_capsule({-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f);
  const Manifold first = collide(ground, at({0.0f, -0.5f}), capsule, at({0.0f, 0.245f}, 0.01f), 0.02f);
  const Manifold second = collide(ground, at({0.0f, -0.5f}), capsule, at({0.001f, 0.2449f}, 0.0101f), 0.02f);
  ASSERT_EQ(first.point_count, 2);
  ASSERT_EQ(second.point_count, 2);
  for (int i = 0; i < 2; ++i) EXPECT_EQ(first.points[i].feature_id, second.points[i].feature_id);
}

TEST(CollideCapsuleCircle, SideAndCap) {
  const Shape capsule = make_capsule({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f);
  const Circle circle{0.5f};
  // Above the side: normal +y, depth 0.05.
  Manifold side = collide(capsule, at({0.0f, 0.0f}), Shape(circle), at({0.4f, 0.7f}));
  ASSERT_EQ(side.point_count, 1);
  expect_vec_near(side.normal, {0.0f, 1.0f}, tolerance());
  EXPECT_NEAR(side.points[0].depth, 0.05f, tolerance());
  // Beyond the cap along a diagonal: normal from the cap centre.
  const vec2 direction = glm::normalize(vec2(1.0f, 1.0f));
  const vec2 centre = vec2(1.0f, 0.0f) + 0.7f * direction;
  Manifold cap = collide(capsule, at({0.0f, 0.0f}), Shape(circle), at(centre));
  ASSERT_EQ(cap.point_count, 1);
  expect_vec_near(cap.normal, direction, tolerance());
  EXPECT_NEAR(cap.points[0].depth, 0.05f, tolerance());
  expect_swapped(cap, collide(Shape(circle), at(centre), capsule, at({0.0f, 0.0f})), tolerance());
}

TEST(CollideSegment, CircleOnSegmentAndBeyondItsEnd) {
  const Shape segment = make_segment({-2.0f, 0.0f}, {2.0f, 0.0f});
  const Shape ball = make_circle(0.5f);
  const Manifold on = collide(segment, at({0.0f, 0.0f}), ball, at({1.0f, 0.49f}));
  ASSERT_EQ(on.point_count, 1);
  expect_vec_near(on.normal, {0.0f, 1.0f}, tolerance());
  EXPECT_NEAR(on.points[0].depth, 0.01f, tolerance());
  // Below the segment the normal points down: a segment is two-sided.
  const Manifold below = collide(segment, at({0.0f, 0.0f}), ball, at({1.0f, -0.49f}));
  ASSERT_EQ(below.point_count, 1);
  expect_vec_near(below.normal, {0.0f, -1.0f}, tolerance());
  // On the segment's line beyond its end: the end's normal.
  const Manifold end = collide(segment, at({0.0f, 0.0f}), ball, at({2.3f, 0.0f}));
  ASSERT_EQ(end.point_count, 1);
  expect_vec_near(end.normal, {1.0f, 0.0f}, tolerance());
  EXPECT_NEAR(end.points[0].depth, 0.2f, tolerance());
}

TEST(CollideSegment, BoxOnSegmentTwoPoints) {
  const Shape segment = make_segment({-2.0f, 0.0f}, {2.0f, 0.0f});
  const Shape box = make_oriented_box({0.5f, 0.25f});
  const Manifold manifold = collide(segment, at({0.0f, 0.0f}), box, at({0.3f, 0.24f}), 0.02f);
  ASSERT_EQ(manifold.point_count, 2);
  expect_vec_near(manifold.normal, {0.0f, 1.0f}, tolerance());
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(manifold.points[i].depth, 0.01f, tolerance());
}

TEST(CollideRoundedPolygon, RoundingZeroIsTodaysPolygonBitForBit) {
  vec2 centroid_sharp, centroid_rounded;
  const Shape sharp = make_polygon(pentagon, 5, &centroid_sharp);
  const Shape rounded = make_rounded_polygon(pentagon, 5, 0.0f, &centroid_rounded);
  ASSERT_EQ(rounded.type(), ShapeType::Polygon);
  EXPECT_EQ(centroid_sharp, centroid_rounded);
  EXPECT_EQ(rounded.polygon().count, sharp.polygon().count);
  EXPECT_EQ(rounded.polygon().rounding, 0.0f);
  EXPECT_EQ(rounded.polygon().radius, sharp.polygon().radius);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(rounded.polygon().vertices[i], sharp.polygon().vertices[i]);
    EXPECT_EQ(rounded.polygon().normals[i], sharp.polygon().normals[i]);
  }
  // The jump table sends a rounding-0 polygon to the tutorial's functions.
  const Shape ground = make_box({5.0f, 0.5f});
  const Manifold expected =
      collide_box_polygon(ground.box(), at({0.0f, -0.5f}), sharp.polygon(), at({0.0f, 0.4f}, 0.1f), 0.02f);
  const Manifold actual = collide(ground, at({0.0f, -0.5f}), rounded, at({0.0f, 0.4f}, 0.1f), 0.02f);
  ASSERT_EQ(actual.point_count, expected.point_count);
  EXPECT_EQ(actual.normal, expected.normal);
  for (int i = 0; i < actual.point_count; ++i) {
    EXPECT_EQ(actual.points[i].point, expected.points[i].point);
    EXPECT_EQ(actual.points[i].depth, expected.points[i].depth);
    EXPECT_EQ(actual.points[i].feature_id, expected.points[i].feature_id);
  }
}

TEST(CollideRoundedPolygon, FlatOnGroundDepthCountsTheRounding) {
  // A 1 x 0.5 box rounded by 0.1 whose bottom edge (core) is 0.1 above the ground: touching.
  const vec2 box[4] = {{-0.5f, -0.25f}, {0.5f, -0.25f}, {0.5f, 0.25f}, {-0.5f, 0.25f}};
  const Shape rounded = make_rounded_polygon(box, 4, 0.1f);
  const Shape ground = make_box({5.0f, 0.5f});
  const Manifold touching = collide(ground, at({0.0f, -0.5f}), rounded, at({0.0f, 0.35f}), 0.02f);
  ASSERT_EQ(touching.point_count, 2);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(touching.points[i].depth, 0.0f, tolerance());
  const Manifold deep = collide(ground, at({0.0f, -0.5f}), rounded, at({0.0f, 0.33f}), 0.02f);
  ASSERT_EQ(deep.point_count, 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(deep.points[i].depth, 0.02f, tolerance());
    EXPECT_NEAR(deep.points[i].point.y, -0.01f, tolerance());
  }
}

// A rounded corner meets others as the circle of the rounding radius about the vertex would:
// the same normal, depth and point.
TEST(CollideRoundedPolygon, CornerContactIsTheCirclesContact) {
  const vec2 box[4] = {{-0.5f, -0.25f}, {0.5f, -0.25f}, {0.5f, 0.25f}, {-0.5f, 0.25f}};
  const float rounding = 0.1f;
  const Shape rounded = make_rounded_polygon(box, 4, rounding);
  const Transform pose = at({0.3f, 0.9f}, -0.7f);  // tipped onto its lower-right corner
  const vec2 corner = pose.apply(rounded.polygon().vertices[1]);
  const Shape corner_circle = make_circle(rounding);
  // Against a tilted ground polygon, a box and a circle: each as the corner's circle.
  const std::vector<Placed> others = {
      {make_oriented_box({3.0f, 0.5f}), at(corner + vec2(0.0f, -0.58f) + vec2(0.2f, 0.0f), 0.0f)},
      {make_oriented_box({3.0f, 0.5f}),
       Transform{corner + Rotation::from_angle(0.2f).rotate(vec2(0.3f, -0.585f)), Rotation::from_angle(0.2f)}},
      {make_circle(0.4f), at(corner + glm::normalize(vec2(0.3f, -1.0f)) * 0.49f)}};
  for (const Placed& other : others) {
    const Manifold expected = collide(other.shape, other.transform, corner_circle, at(corner), 0.02f);
    const Manifold actual = collide(other.shape, other.transform, rounded, pose, 0.02f);
    ASSERT_EQ(expected.point_count, 1);
    ASSERT_EQ(actual.point_count, 1);
    expect_vec_near(actual.normal, expected.normal, 1e-5f);
    EXPECT_NEAR(actual.points[0].depth, expected.points[0].depth, 1e-5f);
    expect_vec_near(actual.points[0].point, expected.points[0].point, 1e-5f);
  }
}

TEST(CollideRoundedPolygon, CirclesAtTheEdgeAndTheCorner) {
  const vec2 box[4] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
  const Shape rounded = make_rounded_polygon(box, 4, 0.2f);
  const Shape ball = make_circle(0.3f);
  const Manifold face = collide(rounded, at({0.0f, 0.0f}), ball, at({0.1f, 0.99f}));
  ASSERT_EQ(face.point_count, 1);
  expect_vec_near(face.normal, {0.0f, 1.0f}, tolerance());
  EXPECT_NEAR(face.points[0].depth, 0.01f, tolerance());
  const vec2 direction = glm::normalize(vec2(1.0f, 2.0f));
  const vec2 centre = vec2(0.5f, 0.5f) + 0.49f * direction;
  const Manifold corner = collide(rounded, at({0.0f, 0.0f}), ball, at(centre));
  ASSERT_EQ(corner.point_count, 1);
  expect_vec_near(corner.normal, direction, tolerance());
  EXPECT_NEAR(corner.points[0].depth, 0.01f, tolerance());
}

// Same-kind pairs in clear (not near-tie) contact: the two orders mirror each other.
TEST(CollisionTable, SameKindPairsMirrored) {
  const vec2 box[4] = {{-0.5f, -0.25f}, {0.5f, -0.25f}, {0.5f, 0.25f}, {-0.5f, 0.25f}};
  const Shape capsule = make_capsule({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f);
  const Shape short_capsule = make_capsule({-0.5f, 0.0f}, {0.5f, 0.0f}, 0.2f);
  const Shape standing = make_capsule({0.0f, -0.5f}, {0.0f, 0.5f}, 0.2f);
  const Shape segment = make_segment({-1.0f, 0.0f}, {1.0f, 0.0f});
  const Shape rounded = make_rounded_polygon(box, 4, 0.1f);
  const Shape rounded_small = make_rounded_polygon(pentagon, 5, 0.05f);
  const Shape sharp = make_polygon(box, 4);
  struct Pair {
    Placed a, b;
  };
  const std::vector<Pair> pairs = {
      {{capsule, at({0.0f, 0.0f})}, {short_capsule, at({0.3f, 0.44f}, 0.05f)}},
      {{capsule, at({0.0f, 0.0f})}, {standing, at({0.3f, 0.93f}, 0.2f)}},
      {{capsule, at({0.0f, 0.0f})}, {capsule, at({2.3f, 0.1f}, 0.4f)}},
      {{segment, at({0.0f, 0.0f})}, {segment, at({0.3f, 1.01f}, 1.5707964f)}},
      {{rounded, at({0.0f, 0.0f})}, {rounded, at({0.2f, 0.68f}, 0.1f)}},
      {{rounded, at({0.0f, 0.0f})}, {rounded_small, at({0.7f, 1.1f}, 0.6f)}},
      {{rounded, at({0.0f, 0.0f})}, {sharp, at({-0.3f, 0.58f}, -0.05f)}},
  };
  for (const Pair& pair : pairs) {
    SCOPED_TRACE("A " + describe(pair.a) + ", B " + describe(pair.b));
    const Manifold manifold = collide(pair.a.shape, pair.a.transform, pair.b.shape, pair.b.transform, 0.02f);
    const Manifold swapped = collide(pair.b.shape, pair.b.transform, pair.a.shape, pair.a.transform, 0.02f);
    ASSERT_GT(manifold.point_count, 0);
    expect_swapped(manifold, swapped, tolerance(4.0f));
  }
}

}  // namespace
}  // namespace impulse2d
