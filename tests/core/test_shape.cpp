/// @file test_shape.cpp
/// Shape validation, mass properties against closed forms, bounds, point and ray queries.

#include "core/error.h"
#include "core/shape.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace impulse2d {
namespace {

/// Absolute tolerance for results of a handful of float operations on values of size `scale`:
/// 16 float epsilons relative, well above the few roundings involved, far below any mistake.
float tolerance(float scale = 1.0f) { return 16.0f * FLT_EPSILON * scale; }

constexpr float pi = 3.14159265358979323846f;
const float not_a_number = std::numeric_limits<float>::quiet_NaN();
const float infinity = std::numeric_limits<float>::infinity();

void expect_vec_near(vec2 actual, vec2 expected, float abs_error) {
  EXPECT_NEAR(actual.x, expected.x, abs_error);
  EXPECT_NEAR(actual.y, expected.y, abs_error);
}

/// Runs `make` and expects an `Error` whose message contains every one of `fragments`.
template <typename Make>
void expect_error(Make make, const std::vector<std::string>& fragments) {
  try {
    make();
    ADD_FAILURE() << "no Error thrown; expected one mentioning " << fragments.front();
  } catch (const Error& error) {
    const std::string message = error.what();
    for (const std::string& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "message \"" << message << "\" lacks \"" << fragment << "\"";
    }
  }
}

Shape polygon_from(const std::vector<vec2>& vertices, vec2* centroid = nullptr) {
  return make_polygon(vertices.data(), static_cast<int>(vertices.size()), centroid);
}

Transform at(vec2 position, float angle = 0.0f) { return {position, Rotation::from_angle(angle)}; }

// ---- validation ------------------------------------------------------------------------

TEST(ShapeValidation, CircleRadiusMustBeFinitePositive) {
  for (float radius : {0.0f, -1.0f, not_a_number, infinity}) {
    expect_error([&] { make_circle(radius); }, {"make_circle", "radius"});
  }
  EXPECT_EQ(make_circle(0.25f).circle().radius, 0.25f);
}

TEST(ShapeValidation, BoxHalfExtentsMustBeFinitePositive) {
  expect_error([] { make_box(vec2(0.0f, 1.0f)); }, {"make_box", "half_extents.x"});
  expect_error([] { make_box(vec2(1.0f, -1.0f)); }, {"make_box", "half_extents.y"});
  expect_error([] { make_box(vec2(not_a_number, 1.0f)); }, {"make_box", "half_extents.x"});
  expect_error([] { make_box(vec2(1.0f, infinity)); }, {"make_box", "half_extents.y"});
  expect_error([] { make_oriented_box(vec2(1.0f, 0.0f)); },
               {"make_oriented_box", "half_extents.y"});
  const Shape box = make_box(vec2(1.0f, 2.0f));
  EXPECT_EQ(box.type(), ShapeType::Box);
  EXPECT_EQ(box.box().half_extents, vec2(1.0f, 2.0f));
}

TEST(ShapeValidation, PolygonVertexCount) {
  const std::vector<vec2> two = {{0, 0}, {1, 0}};
  expect_error([&] { polygon_from(two); }, {"make_polygon", "count", "got 2"});
  std::vector<vec2> nine;
  for (int i = 0; i < 9; ++i) {
    const float angle = 2.0f * pi * static_cast<float>(i) / 9.0f;
    nine.push_back(vec2(std::cos(angle), std::sin(angle)));
  }
  expect_error([&] { polygon_from(nine); }, {"make_polygon", "count", "got 9"});
  expect_error([] { make_polygon(nullptr, 3); }, {"make_polygon", "null"});
}

TEST(ShapeValidation, PolygonNonFiniteVertex) {
  expect_error(
      [] {
        polygon_from({{0, 0}, {not_a_number, 0}, {0, 1}});
      },
      {"make_polygon", "vertex 1", "not finite"});
  expect_error(
      [] {
        polygon_from({{0, 0}, {1, 0}, {0, infinity}});
      },
      {"make_polygon", "vertex 2", "not finite"});
}

TEST(ShapeValidation, PolygonClockwise) {
  expect_error(
      [] {
        polygon_from({{0, 0}, {0, 1}, {1, 1}, {1, 0}});
      },
      {"make_polygon", "clockwise"});
}

TEST(ShapeValidation, PolygonConcave) {
  // A square with its top pushed in: vertex 3 turns right.
  expect_error(
      [] {
        polygon_from({{0, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}});
      },
      {"make_polygon", "not convex at vertex 3"});
}

TEST(ShapeValidation, PolygonCollinear) {
  expect_error(
      [] {
        polygon_from({{0, 0}, {1, 0}, {2, 0}, {1, 1}});
      },
      {"make_polygon", "vertices 0, 1, 2", "collinear"});
}

TEST(ShapeValidation, PolygonRepeatedPoint) {
  expect_error(
      [] {
        polygon_from({{0, 0}, {1, 0}, {1, 0}, {0, 1}});
      },
      {"make_polygon", "vertices 1 and 2", "repeated"});
  // Repeated but not adjacent.
  expect_error(
      [] {
        polygon_from({{0, 0}, {1, 0}, {0, 0}, {0, 1}});
      },
      {"make_polygon", "vertices 0 and 2", "repeated"});
}

TEST(ShapeValidation, PolygonSelfOverlapping) {
  // A pentagram: every turn is to the left, but the outline winds around twice.
  std::vector<vec2> star;
  for (int k = 0; k < 5; ++k) {
    const float angle = 0.5f * pi + 2.0f * pi * static_cast<float>((2 * k) % 5) / 5.0f;
    star.push_back(vec2(std::cos(angle), std::sin(angle)));
  }
  expect_error([&] { polygon_from(star); }, {"make_polygon", "self-overlapping"});
  // A bow tie: its two lobes cancel to zero signed area.
  expect_error([] { polygon_from({{0, 0}, {1, 1}, {1, 0}, {0, 1}}); }, {"make_polygon"});
}

TEST(ShapeValidation, PolygonNearZeroArea) {
  expect_error(
      [] {
        polygon_from({{0, 0}, {1, 0}, {0.5f, 1e-7f}});
      },
      {"make_polygon", "near zero"});
}

TEST(ShapeValidation, PolygonIsRecentredWithUnitOutwardNormals) {
  vec2 centroid;
  const Shape triangle = polygon_from({{0, 0}, {3, 0}, {0, 3}}, &centroid);
  ASSERT_EQ(triangle.type(), ShapeType::Polygon);
  ASSERT_EQ(triangle.polygon().count, 3);
  expect_vec_near(centroid, vec2(1.0f, 1.0f), tolerance());
  expect_vec_near(triangle.polygon().vertices[0], vec2(-1.0f, -1.0f), tolerance(3.0f));
  expect_vec_near(triangle.polygon().vertices[1], vec2(2.0f, -1.0f), tolerance(3.0f));
  expect_vec_near(triangle.polygon().normals[0], vec2(0.0f, -1.0f), tolerance());
  const float diagonal = std::sqrt(0.5f);
  expect_vec_near(triangle.polygon().normals[1], vec2(diagonal, diagonal), tolerance());
  expect_vec_near(triangle.polygon().normals[2], vec2(-1.0f, 0.0f), tolerance());
}

TEST(ShapeValidation, OrientedBoxIsACounterClockwiseRectangle) {
  const Shape box = make_oriented_box(vec2(2.0f, 1.0f));
  ASSERT_EQ(box.type(), ShapeType::Polygon);
  ASSERT_EQ(box.polygon().count, 4);
  EXPECT_EQ(box.polygon().vertices[0], vec2(-2.0f, -1.0f));
  EXPECT_EQ(box.polygon().vertices[2], vec2(2.0f, 1.0f));
  EXPECT_EQ(box.polygon().normals[1], vec2(1.0f, 0.0f));
}

// ---- mass ------------------------------------------------------------------------------

TEST(ShapeMass, DiscIsHalfMrSquared) {
  const MassData mass = compute_mass(make_circle(2.0f), 3.0f);
  EXPECT_NEAR(mass.area, 4.0f * pi, tolerance(4.0f * pi));
  EXPECT_NEAR(mass.mass, 12.0f * pi, tolerance(12.0f * pi));
  // m r^2 / 2, not the reference code's m r^2.
  EXPECT_NEAR(mass.inertia, 24.0f * pi, tolerance(24.0f * pi));
  EXPECT_EQ(mass.centroid, vec2(0.0f, 0.0f));
}

TEST(ShapeMass, BoxUsesFullWidthAndHeight) {
  const MassData mass = compute_mass(make_box(vec2(1.5f, 0.5f)), 2.0f);  // 3 x 1
  EXPECT_FLOAT_EQ(mass.area, 3.0f);
  EXPECT_FLOAT_EQ(mass.mass, 6.0f);
  EXPECT_NEAR(mass.inertia, 6.0f * (9.0f + 1.0f) / 12.0f, tolerance(5.0f));
  const MassData oriented = compute_mass(make_oriented_box(vec2(1.5f, 0.5f)), 2.0f);
  EXPECT_NEAR(oriented.mass, mass.mass, tolerance(6.0f));
  EXPECT_NEAR(oriented.inertia, mass.inertia, tolerance(5.0f));
}

TEST(ShapeMass, RightTriangle) {
  // Legs 3 (x) and 4 (y): centroid at a third of each leg; polar moment about the centroid
  // m (a^2 + b^2) / 18.
  const std::vector<vec2> triangle = {{0, 0}, {3, 0}, {0, 4}};
  const MassData mass = compute_polygon_mass(triangle.data(), 3, 2.0f);
  EXPECT_NEAR(mass.area, 6.0f, tolerance(6.0f));
  EXPECT_NEAR(mass.mass, 12.0f, tolerance(12.0f));
  expect_vec_near(mass.centroid, vec2(1.0f, 4.0f / 3.0f), tolerance(4.0f));
  EXPECT_NEAR(mass.inertia, 12.0f * 25.0f / 18.0f, tolerance(17.0f));
}

TEST(ShapeMass, OffsetPolygonInertiaIsAboutItsCentroid) {
  // A house: a 2 x 2 square with a roof triangle of base 2 and height 1, far from the origin.
  // Expected values by composing the two parts with the parallel axis theorem (in double).
  const double offset_x = 5.0, offset_y = -3.0;
  const double square_mass = 4.0, square_inertia = 4.0 * (4.0 + 4.0) / 12.0;
  const double roof_mass = 1.0,
               roof_inertia = roof_mass * (4.0 + 2.0 + 2.0) / 36.0;  // m/36 sum of squared sides
  const double square_cy = 1.0, roof_cy = 2.0 + 1.0 / 3.0;
  const double total_mass = square_mass + roof_mass;
  const double cy = (square_mass * square_cy + roof_mass * roof_cy) / total_mass;
  const double inertia = square_inertia + square_mass * (square_cy - cy) * (square_cy - cy) +
                         roof_inertia + roof_mass * (roof_cy - cy) * (roof_cy - cy);

  std::vector<vec2> house = {{0, 0}, {2, 0}, {2, 2}, {1, 3}, {0, 2}};
  for (vec2& vertex : house) vertex += vec2(offset_x, offset_y);
  const MassData mass = compute_polygon_mass(house.data(), 5, 1.0f);
  EXPECT_NEAR(mass.mass, total_mass, tolerance(5.0f));
  expect_vec_near(mass.centroid,
                  vec2(static_cast<float>(offset_x + 1.0), static_cast<float>(offset_y + cy)),
                  tolerance(5.0f));
  EXPECT_NEAR(mass.inertia, inertia, tolerance(4.0f));
  // The reference code's mistake, inertia about the origin, would be m |c|^2 larger.
  const double about_origin = inertia + total_mass * ((offset_x + 1.0) * (offset_x + 1.0) +
                                                      (offset_y + cy) * (offset_y + cy));
  EXPECT_GT(std::fabs(mass.inertia - about_origin), 100.0);

  // make_polygon moves the centroid to the origin; compute_mass then agrees.
  vec2 centroid;
  const Shape shape = polygon_from(house, &centroid);
  expect_vec_near(centroid, mass.centroid, tolerance(5.0f));
  const MassData shape_mass = compute_mass(shape, 1.0f);
  expect_vec_near(shape_mass.centroid, vec2(0.0f, 0.0f), tolerance(5.0f));
  EXPECT_NEAR(shape_mass.inertia, inertia, tolerance(4.0f));
}

TEST(ShapeMass, DensityZeroIsMasslessAndNegativeIsAnError) {
  EXPECT_EQ(compute_mass(make_circle(1.0f), 0.0f).mass, 0.0f);
  expect_error([] { compute_mass(make_circle(1.0f), -1.0f); }, {"compute_mass", "density"});
  expect_error([] { compute_mass(make_circle(1.0f), not_a_number); }, {"compute_mass", "density"});
  const std::vector<vec2> clockwise = {{0, 0}, {0, 1}, {1, 0}};
  expect_error([&] { compute_polygon_mass(clockwise.data(), 3, 1.0f); },
               {"compute_polygon_mass", "area"});
}

// ---- bounds and point queries ----------------------------------------------------------

TEST(ShapeBounds, CircleBoxPolygon) {
  const Aabb circle = compute_aabb(make_circle(0.5f), at(vec2(1.0f, 2.0f)));
  EXPECT_EQ(circle.lower, vec2(0.5f, 1.5f));
  EXPECT_EQ(circle.upper, vec2(1.5f, 2.5f));

  // A box ignores the rotation of its transform.
  const Aabb box = compute_aabb(make_box(vec2(2.0f, 1.0f)), at(vec2(1.0f, 1.0f), 0.7f));
  EXPECT_EQ(box.lower, vec2(-1.0f, 0.0f));
  EXPECT_EQ(box.upper, vec2(3.0f, 2.0f));

  // A polygon turns: a 4 x 2 rectangle a quarter turn round becomes 2 x 4.
  const Aabb turned =
      compute_aabb(make_oriented_box(vec2(2.0f, 1.0f)), at(vec2(0.0f, 0.0f), 0.5f * pi));
  expect_vec_near(turned.lower, vec2(-1.0f, -2.0f), tolerance(2.0f));
  expect_vec_near(turned.upper, vec2(1.0f, 2.0f), tolerance(2.0f));
}

TEST(ShapeContains, InsideOnBoundaryAndOutside) {
  const Shape circle = make_circle(1.0f);
  EXPECT_TRUE(shape_contains_point(circle, at(vec2(1.0f, 0.0f)), vec2(2.0f, 0.0f)));
  EXPECT_FALSE(shape_contains_point(circle, at(vec2(1.0f, 0.0f)), vec2(2.0f, 0.001f)));

  // The box ignores rotation: (1.4, 0) is inside the unrotated 3 x 1 box only.
  const Shape box = make_box(vec2(1.5f, 0.5f));
  EXPECT_TRUE(shape_contains_point(box, at(vec2(0.0f, 0.0f), 0.5f * pi), vec2(1.4f, 0.0f)));
  EXPECT_FALSE(shape_contains_point(box, at(vec2(0.0f, 0.0f)), vec2(0.0f, 0.6f)));

  vec2 centroid;
  const Shape triangle = polygon_from({{0, 0}, {2, 0}, {0, 2}}, &centroid);
  const Transform placed = at(centroid);
  EXPECT_TRUE(shape_contains_point(triangle, placed, vec2(0.5f, 0.5f)));
  EXPECT_TRUE(shape_contains_point(triangle, placed, vec2(1.0f, 0.5f)));
  EXPECT_FALSE(shape_contains_point(triangle, placed, vec2(1.1f, 1.1f)));
  EXPECT_FALSE(shape_contains_point(triangle, placed, vec2(0.5f, -0.01f)));
}

// ---- ray casts -------------------------------------------------------------------------

TEST(ShapeRaycast, Circle) {
  const Shape circle = make_circle(1.0f);
  ShapeRayHit hit;
  ASSERT_TRUE(
      raycast_shape(circle, at(vec2(0.0f, 0.0f)), vec2(-3.0f, 0.0f), vec2(4.0f, 0.0f), &hit));
  EXPECT_FLOAT_EQ(hit.fraction, 0.5f);
  expect_vec_near(hit.normal, vec2(-1.0f, 0.0f), tolerance());
  // Off-centre: enters at (-0.6, 0.8), 2.4 along a ray of length 4.
  ASSERT_TRUE(
      raycast_shape(circle, at(vec2(0.0f, 0.0f)), vec2(-3.0f, 0.8f), vec2(4.0f, 0.0f), &hit));
  EXPECT_NEAR(hit.fraction, 0.6f, tolerance());
  expect_vec_near(hit.normal, vec2(-0.6f, 0.8f), tolerance());

  EXPECT_FALSE(raycast_shape(circle, at(vec2(0.0f, 0.0f)), vec2(-3.0f, 1.5f), vec2(4.0f, 0.0f),
                             &hit));  // passes above
  EXPECT_FALSE(raycast_shape(circle, at(vec2(0.0f, 0.0f)), vec2(-3.0f, 0.0f), vec2(1.5f, 0.0f),
                             &hit));  // too short
  EXPECT_FALSE(raycast_shape(circle, at(vec2(0.0f, 0.0f)), vec2(-3.0f, 0.0f), vec2(-4.0f, 0.0f),
                             &hit));  // away
  EXPECT_FALSE(raycast_shape(circle, at(vec2(0.0f, 0.0f)), vec2(0.2f, 0.0f), vec2(4.0f, 0.0f),
                             &hit));  // inside
}

TEST(ShapeRaycast, BoxSlabsIgnoreRotation) {
  const Shape box = make_box(vec2(1.0f, 0.5f));
  for (float angle : {0.0f, 0.3f}) {
    const Transform placed = at(vec2(2.0f, 1.0f), angle);
    ShapeRayHit hit;
    ASSERT_TRUE(raycast_shape(box, placed, vec2(0.0f, 1.25f), vec2(4.0f, 0.0f), &hit));
    EXPECT_FLOAT_EQ(hit.fraction, 0.25f);
    EXPECT_EQ(hit.normal, vec2(-1.0f, 0.0f));
    ASSERT_TRUE(raycast_shape(box, placed, vec2(2.5f, 3.0f), vec2(0.0f, -4.0f), &hit));
    EXPECT_FLOAT_EQ(hit.fraction, 0.375f);
    EXPECT_EQ(hit.normal, vec2(0.0f, 1.0f));
    // Diagonal, entering through the right face at (3, 1): 0.5 along.
    ASSERT_TRUE(raycast_shape(box, placed, vec2(4.0f, 2.0f), vec2(-2.0f, -2.0f), &hit));
    EXPECT_FLOAT_EQ(hit.fraction, 0.5f);
    EXPECT_EQ(hit.normal, vec2(1.0f, 0.0f));
    EXPECT_FALSE(
        raycast_shape(box, placed, vec2(0.0f, 2.0f), vec2(4.0f, 0.0f), &hit));  // parallel, outside
    EXPECT_FALSE(
        raycast_shape(box, placed, vec2(0.0f, 0.0f), vec2(2.0f, 4.0f), &hit));  // misses the corner
    EXPECT_FALSE(raycast_shape(box, placed, vec2(2.0f, 1.0f), vec2(4.0f, 0.0f), &hit));  // inside
  }
}

TEST(ShapeRaycast, PolygonClipsAgainstEdgePlanes) {
  vec2 centroid;
  const Shape triangle = polygon_from({{0, 0}, {2, 0}, {0, 2}}, &centroid);
  const Transform placed = at(centroid);
  ShapeRayHit hit;
  ASSERT_TRUE(raycast_shape(triangle, placed, vec2(3.0f, 3.0f), vec2(-4.0f, -4.0f), &hit));
  EXPECT_NEAR(hit.fraction, 0.5f, tolerance());
  const float diagonal = std::sqrt(0.5f);
  expect_vec_near(hit.normal, vec2(diagonal, diagonal), tolerance());
  ASSERT_TRUE(raycast_shape(triangle, placed, vec2(-1.0f, 0.5f), vec2(2.0f, 0.0f), &hit));
  EXPECT_NEAR(hit.fraction, 0.5f, tolerance());
  expect_vec_near(hit.normal, vec2(-1.0f, 0.0f), tolerance());
  EXPECT_FALSE(
      raycast_shape(triangle, placed, vec2(-1.0f, 3.0f), vec2(4.0f, 0.0f), &hit));  // misses
  EXPECT_FALSE(
      raycast_shape(triangle, placed, vec2(0.5f, 0.5f), vec2(4.0f, 0.0f), &hit));  // inside

  // A turned polygon: a 2 x 1 rectangle a quarter turn round spans x in [-0.5, 0.5].
  const Shape rectangle = make_oriented_box(vec2(1.0f, 0.5f));
  ASSERT_TRUE(raycast_shape(rectangle, at(vec2(0.0f, 0.0f), 0.5f * pi), vec2(-2.0f, 0.0f),
                            vec2(4.0f, 0.0f), &hit));
  EXPECT_NEAR(hit.fraction, 0.375f, tolerance());
  expect_vec_near(hit.normal, vec2(-1.0f, 0.0f), tolerance());
}

// ---- capsules, segments, rounded polygons (issue 31) -------------------------------------

TEST(ShapeValidation, CapsuleAndSegmentEnds) {
  expect_error([] { make_capsule({1.0f, 2.0f}, {1.0f, 2.0f}, 0.5f); },
               {"make_capsule", "center1 and center2", "use a circle"});
  for (float radius : {0.0f, -0.1f, not_a_number, infinity}) {
    expect_error([&] { make_capsule({0.0f, 0.0f}, {1.0f, 0.0f}, radius); }, {"make_capsule", "radius"});
  }
  expect_error([] { make_capsule({not_a_number, 0.0f}, {1.0f, 0.0f}, 0.5f); },
               {"make_capsule", "center1", "not finite"});
  expect_error([] { make_segment({3.0f, 1.0f}, {3.0f, 1.0f}); },
               {"make_segment", "point1 and point2", "length"});
  expect_error([] { make_segment({0.0f, 0.0f}, {infinity, 0.0f}); },
               {"make_segment", "point2", "not finite"});
  expect_error([] {
    const vec2 square[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    make_rounded_polygon(square, 4, -0.01f);
  }, {"make_rounded_polygon", "radius", ">= 0"});
}

TEST(ShapeValidation, CapsuleAndSegmentAreCentredOnTheirMidpoint) {
  vec2 centroid;
  const Shape capsule = make_capsule({1.0f, 2.0f}, {3.0f, 2.0f}, 0.5f, &centroid);
  expect_vec_near(centroid, {2.0f, 2.0f}, tolerance());
  expect_vec_near(capsule.capsule().center1, {-1.0f, 0.0f}, tolerance());
  expect_vec_near(capsule.capsule().center2, {1.0f, 0.0f}, tolerance());
  const Shape segment = make_segment({-4.0f, 1.0f}, {0.0f, 3.0f}, &centroid);
  expect_vec_near(centroid, {-2.0f, 2.0f}, tolerance());
  expect_vec_near(segment.segment().point1, {-2.0f, -1.0f}, tolerance());
  expect_vec_near(segment.segment().point2, {2.0f, 1.0f}, tolerance());
}

/// Relative difference, for mass properties against closed forms.
double relative(double actual, double expected) { return std::fabs(actual - expected) / std::fabs(expected); }

// Capsule of length L and radius r: a rectangle L x 2r and two half discs. Integrated here in
// polar coordinates about each cap centre (h = L/2 from the centroid), independently of
// shape.cpp's parallel-axis route: per half disc
// int (h^2 + 2 h rho cos(phi) + rho^2) rho drho dphi = pi r^2 h^2 / 2 + 4 h r^3 / 3 + pi r^4 / 4.
TEST(ShapeMass, CapsuleMatchesTheClosedForm) {
  for (const auto& [length, radius] : {std::pair<double, double>{2.0, 0.25}, {1.0, 1.0}, {0.1, 3.0}, {7.5, 0.05}}) {
    const double density = 1.7;
    const Shape capsule = make_capsule({0.0f, 0.0f}, {static_cast<float>(length) * 0.6f, static_cast<float>(length) * 0.8f},
                                       static_cast<float>(radius));
    const MassData mass = compute_mass(capsule, static_cast<float>(density));
    const double pi_d = 3.14159265358979323846;
    const double h = 0.5 * length;
    const double area = pi_d * radius * radius + 2.0 * radius * length;
    const double rectangle = 2.0 * radius * length * (length * length + 4.0 * radius * radius) / 12.0;
    const double caps = 2.0 * (pi_d * radius * radius * h * h / 2.0 + 4.0 * h * radius * radius * radius / 3.0 +
                               pi_d * radius * radius * radius * radius / 4.0);
    EXPECT_LT(relative(mass.area, area), 1e-6) << length << " x " << radius;
    EXPECT_LT(relative(mass.mass, density * area), 1e-6);
    EXPECT_LT(relative(mass.inertia, density * (rectangle + caps)), 1e-6) << length << " x " << radius;
    expect_vec_near(mass.centroid, {0.0f, 0.0f}, tolerance(static_cast<float>(length)));
  }
}

// A square of half side a rounded by r: core square, four edge strips 2a x r, four quarter discs
// about the corners (each, in polar coordinates about its corner v = (a, a):
// |v|^2 pi r^2 / 4 + 4 a r^3 / 3 + pi r^4 / 8).
TEST(ShapeMass, RoundedSquareMatchesTheClosedForm) {
  for (const auto& [a, r] : {std::pair<double, double>{0.5, 0.1}, {1.0, 1.0}, {0.05, 2.0}, {3.0, 0.01}}) {
    const float af = static_cast<float>(a);
    const vec2 square[4] = {{-af, -af}, {af, -af}, {af, af}, {-af, af}};
    const double density = 0.8;
    const MassData mass = compute_mass(make_rounded_polygon(square, 4, static_cast<float>(r)), static_cast<float>(density));
    const double pi_d = 3.14159265358979323846;
    const double area = 4.0 * a * a + 8.0 * a * r + pi_d * r * r;
    const double core = 8.0 * a * a * a * a / 3.0;
    const double strip_area = 2.0 * a * r;
    const double strips = 4.0 * (strip_area * (4.0 * a * a + r * r) / 12.0 + strip_area * (a + 0.5 * r) * (a + 0.5 * r));
    const double corners = 4.0 * (2.0 * a * a * pi_d * r * r / 4.0 + 4.0 * a * r * r * r / 3.0 + pi_d * r * r * r * r / 8.0);
    EXPECT_LT(relative(mass.area, area), 1e-6) << a << ", " << r;
    EXPECT_LT(relative(mass.inertia, density * (core + strips + corners)), 1e-6) << a << ", " << r;
    expect_vec_near(mass.centroid, {0.0f, 0.0f}, 1e-6f);
  }
}

// A lopsided rounded triangle: the rounding moves the centroid off the core's, and
// make_rounded_polygon centres the rounded solid. Checked against a fine grid integration
// (independent of the strip-and-sector sums), to its own accuracy.
TEST(ShapeMass, RoundedTriangleAgainstGridIntegration) {
  const vec2 triangle[3] = {{0.0f, 0.0f}, {3.0f, 0.0f}, {0.5f, 1.0f}};
  const float rounding = 0.4f;
  vec2 centroid;
  const Shape shape = make_rounded_polygon(triangle, 3, rounding, &centroid);
  const MassData mass = compute_mass(shape, 1.0f);
  expect_vec_near(mass.centroid, {0.0f, 0.0f}, 1e-6f);
  // Grid over the bounds, in the input coordinates.
  const int cells = 1200;
  const double lower_x = -0.5, upper_x = 3.5, lower_y = -0.5, upper_y = 1.5;
  const double dx = (upper_x - lower_x) / cells, dy = (upper_y - lower_y) / cells;
  double area = 0.0, mx = 0.0, my = 0.0, second = 0.0;
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      const vec2 p(static_cast<float>(lower_x + (i + 0.5) * dx), static_cast<float>(lower_y + (j + 0.5) * dy));
      if (!shape_contains_point(shape, Transform{centroid, Rotation{}}, p)) continue;
      area += dx * dy;
      mx += dx * dy * p.x;
      my += dx * dy * p.y;
      second += dx * dy * (static_cast<double>(p.x) * p.x + static_cast<double>(p.y) * p.y);
    }
  }
  const double cx = mx / area, cy = my / area;
  EXPECT_LT(relative(mass.area, area), 2e-3);
  EXPECT_NEAR(centroid.x, cx, 2e-3);
  EXPECT_NEAR(centroid.y, cy, 2e-3);
  EXPECT_LT(relative(mass.inertia, second - area * (cx * cx + cy * cy)), 3e-3);
  // And the core's centroid (1.1667, 0.3333) is not the rounded one.
  EXPECT_GT(std::fabs(centroid.x - 3.5f / 3.0f) + std::fabs(centroid.y - 1.0f / 3.0f), 1e-2f);
}

TEST(ShapeMass, SegmentIsMassless) {
  const MassData mass = compute_mass(make_segment({-1.0f, 0.0f}, {1.0f, 0.0f}), 5.0f);
  EXPECT_EQ(mass.mass, 0.0f);
  EXPECT_EQ(mass.area, 0.0f);
  EXPECT_EQ(mass.inertia, 0.0f);
}

TEST(ShapeBounds, CapsuleSegmentRoundedPolygon) {
  const Aabb capsule = compute_aabb(make_capsule({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f), at({2.0f, 1.0f}, pi / 2.0f));
  expect_vec_near(capsule.lower, {1.5f, -0.5f}, tolerance(2.0f));
  expect_vec_near(capsule.upper, {2.5f, 2.5f}, tolerance(2.0f));
  const Aabb segment = compute_aabb(make_segment({-1.0f, -2.0f}, {1.0f, 2.0f}), at({0.0f, 0.0f}));
  expect_vec_near(segment.lower, {-1.0f, -2.0f}, tolerance());
  expect_vec_near(segment.upper, {1.0f, 2.0f}, tolerance());
  const vec2 square[4] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
  const Aabb rounded = compute_aabb(make_rounded_polygon(square, 4, 0.25f), at({0.0f, 0.0f}));
  expect_vec_near(rounded.lower, {-1.25f, -1.25f}, tolerance());
  expect_vec_near(rounded.upper, {1.25f, 1.25f}, tolerance());
}

TEST(ShapeContains, CapsuleSegmentRoundedCorner) {
  const Shape capsule = make_capsule({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f);
  EXPECT_TRUE(shape_contains_point(capsule, at({0.0f, 0.0f}), {1.3f, 0.3f}));
  EXPECT_FALSE(shape_contains_point(capsule, at({0.0f, 0.0f}), {1.4f, 0.4f}));
  EXPECT_FALSE(shape_contains_point(make_segment({-1.0f, 0.0f}, {1.0f, 0.0f}), at({0.0f, 0.0f}), {0.0f, 0.0f}));
  const vec2 square[4] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
  const Shape rounded = make_rounded_polygon(square, 4, 0.25f);
  EXPECT_TRUE(shape_contains_point(rounded, at({0.0f, 0.0f}), {1.15f, 1.15f}));   // inside the arc
  EXPECT_FALSE(shape_contains_point(rounded, at({0.0f, 0.0f}), {1.2f, 1.2f}));    // beyond the arc
  EXPECT_TRUE(shape_contains_point(rounded, at({0.0f, 0.0f}), {0.0f, 1.24f}));    // the edge strip
}

TEST(ShapeRaycast, CapsuleSideAndCap) {
  const Shape capsule = make_capsule({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f);
  ShapeRayHit hit;
  ASSERT_TRUE(raycast_shape(capsule, at({0.0f, 0.0f}), {0.2f, 2.0f}, {0.0f, -4.0f}, &hit));
  EXPECT_NEAR(hit.fraction, 1.5f / 4.0f, tolerance());
  expect_vec_near(hit.normal, {0.0f, 1.0f}, tolerance());
  ASSERT_TRUE(raycast_shape(capsule, at({0.0f, 0.0f}), {3.0f, 0.0f}, {-4.0f, 0.0f}, &hit));
  EXPECT_NEAR(hit.fraction, 1.5f / 4.0f, tolerance());
  expect_vec_near(hit.normal, {1.0f, 0.0f}, tolerance());
  EXPECT_FALSE(raycast_shape(capsule, at({0.0f, 0.0f}), {0.0f, 0.0f}, {0.0f, 4.0f}, &hit));  // inside
  EXPECT_FALSE(raycast_shape(capsule, at({0.0f, 0.0f}), {3.0f, 0.6f}, {-6.0f, 0.0f}, &hit));  // misses
}

TEST(ShapeRaycast, SegmentFacesTheRay) {
  const Shape segment = make_segment({-1.0f, 0.0f}, {1.0f, 0.0f});
  ShapeRayHit hit;
  ASSERT_TRUE(raycast_shape(segment, at({0.0f, 1.0f}), {0.5f, 3.0f}, {0.0f, -4.0f}, &hit));
  EXPECT_NEAR(hit.fraction, 0.5f, tolerance());
  expect_vec_near(hit.normal, {0.0f, 1.0f}, tolerance());
  ASSERT_TRUE(raycast_shape(segment, at({0.0f, 1.0f}), {0.5f, -1.0f}, {0.0f, 4.0f}, &hit));
  expect_vec_near(hit.normal, {0.0f, -1.0f}, tolerance());
  EXPECT_FALSE(raycast_shape(segment, at({0.0f, 1.0f}), {1.5f, 3.0f}, {0.0f, -4.0f}, &hit));
}

TEST(ShapeRaycast, RoundedCornerNormalIsRadial) {
  const vec2 square[4] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
  const Shape rounded = make_rounded_polygon(square, 4, 0.5f);
  ShapeRayHit hit;
  // Along the diagonal into the corner at (1, 1): enters at (1, 1) + 0.5 (1, 1)/sqrt(2).
  const vec2 origin(3.0f, 3.0f);
  ASSERT_TRUE(raycast_shape(rounded, at({0.0f, 0.0f}), origin, {-3.0f, -3.0f}, &hit));
  const vec2 entry = vec2(1.0f) + 0.5f * glm::normalize(vec2(1.0f));
  EXPECT_NEAR(hit.fraction, (origin.x - entry.x) / 3.0f, 1e-6f);
  expect_vec_near(hit.normal, glm::normalize(vec2(1.0f)), 1e-6f);
  // Straight down onto the flat top: the edge strip, at y = 1.5.
  ASSERT_TRUE(raycast_shape(rounded, at({0.0f, 0.0f}), {0.3f, 3.0f}, {0.0f, -3.0f}, &hit));
  EXPECT_NEAR(hit.fraction, 0.5f, tolerance());
  expect_vec_near(hit.normal, {0.0f, 1.0f}, tolerance());
}

}  // namespace
}  // namespace impulse2d
