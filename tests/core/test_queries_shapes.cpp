// Shape queries (issue 32): shape casts against analytic times of impact, overlap queries
// against the narrow phase for every pair of shape kinds, filtered ray casts.
#include "core/collide.h"
#include "core/error.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace impulse2d;

namespace {

BodyId add_static(World& world, const Shape& shape, vec2 position, float angle = 0.0f,
                  std::uint32_t layers = 1) {
  BodyDef def;
  def.type = BodyType::Static;
  def.position = position;
  def.angle = angle;
  def.collision_layers = layers;
  return world.create_body(def, shape);
}

Transform at(vec2 position, float angle = 0.0f) { return Transform{position, Rotation::from_angle(angle)}; }

// Deterministic uniform numbers in [lo, hi).
struct Random {
  std::uint32_t state = 12345u;
  float next(float lo, float hi) {
    state = state * 1664525u + 1013904223u;
    return lo + (hi - lo) * static_cast<float>(state >> 8) / 16777216.0f;
  }
};

}  // namespace

// A box cast toward a wall meets it at the analytic time of impact.
TEST(ShapeCast, BoxTowardWallAtTheAnalyticFraction) {
  World world;
  const BodyId wall = add_static(world, make_box({0.5f, 5.0f}), {10.0f, 0.0f});  // face at x = 9.5
  const vec2 translation{20.0f, 0.0f};
  const auto hit = world.cast_shape(make_box({0.5f, 0.5f}), at({0.0f, 0.3f}), translation);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->body, wall);
  EXPECT_NEAR(hit->fraction, (9.5f - 0.5f) / 20.0f, 1e-5f);
  EXPECT_NEAR(hit->normal.x, -1.0f, 1e-5f);
  EXPECT_NEAR(hit->normal.y, 0.0f, 1e-5f);
  EXPECT_NEAR(hit->point.x, 9.5f, 1e-4f);

  // Turned 45 degrees, the box leads with a corner 0.5 sqrt(2) ahead of its centre.
  const auto turned = world.cast_shape(make_box({0.5f, 0.5f}), at({0.0f, 0.0f}, 0.785398163f), translation);
  ASSERT_TRUE(turned.has_value());
  EXPECT_NEAR(turned->fraction, (9.5f - 0.70710678f) / 20.0f, 1e-5f);
  EXPECT_NEAR(turned->point.y, 0.0f, 1e-3f);

  // A circle on a slant: centre path (t*dx, t*dy) meets x = 9.5 - r.
  const vec2 slant{12.0f, 3.0f};
  const auto circle = world.cast_shape(make_circle(0.25f), at({0.0f, -1.0f}), slant);
  ASSERT_TRUE(circle.has_value());
  EXPECT_NEAR(circle->fraction, (9.5f - 0.25f) / 12.0f, 1e-5f);

  // Short of the wall, moving away, or filtered out: no hit.
  EXPECT_FALSE(world.cast_shape(make_box({0.5f, 0.5f}), at({0.0f, 0.0f}), {8.0f, 0.0f}).has_value());
  EXPECT_FALSE(world.cast_shape(make_box({0.5f, 0.5f}), at({0.0f, 0.0f}), {-20.0f, 0.0f}).has_value());
  QueryFilter other_layer;
  other_layer.layers = 2;
  EXPECT_FALSE(world.cast_shape(make_box({0.5f, 0.5f}), at({0.0f, 0.0f}), translation, other_layer).has_value());
  // Already overlapping: fraction 0.
  const auto inside = world.cast_shape(make_circle(0.5f), at({9.6f, 0.0f}), translation);
  ASSERT_TRUE(inside.has_value());
  EXPECT_EQ(inside->fraction, 0.0f);
}

// The first of several bodies along the cast, ties by slot, through the broad phase.
TEST(ShapeCast, FirstOfManyAndPolygonTargets) {
  World world;
  std::vector<BodyId> posts;
  for (int i = 0; i < 20; ++i) {
    posts.push_back(add_static(world, make_oriented_box({0.2f, 0.2f}), {2.0f + 3.0f * static_cast<float>(i), 0.0f},
                               0.785398163f));
  }
  const auto hit = world.cast_shape(make_circle(0.3f), at({-5.0f, 0.0f}), {100.0f, 0.0f});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->body, posts[0]);
  // The diamond's left corner is at 2 - 0.2 sqrt(2).
  EXPECT_NEAR(hit->fraction, (2.0f - 0.28284271f - 0.3f + 5.0f) / 100.0f, 1e-5f);
  EXPECT_NEAR(hit->point.x, 2.0f - 0.28284271f, 1e-4f);
}

// Overlap of a placed shape agrees with the narrow phase for every pair of shape kinds, and
// with the GJK distance away from the boundary.
TEST(OverlapQuery, AgreesWithTheNarrowPhaseForEveryPair) {
  const vec2 triangle[3] = {{-0.5f, -0.4f}, {0.6f, -0.3f}, {0.0f, 0.5f}};
  const std::vector<Shape> shapes = {make_circle(0.5f), make_box({0.6f, 0.3f}), make_polygon(triangle, 3),
                                     make_oriented_box({0.4f, 0.7f})};
  Random random;
  int overlaps = 0, apart = 0;
  for (std::size_t query = 0; query < shapes.size(); ++query) {
    for (std::size_t target = 0; target < shapes.size(); ++target) {
      for (int trial = 0; trial < 300; ++trial) {
        World world;
        const float target_angle = shapes[target].type() == ShapeType::Box ? 0.0f : random.next(-3.0f, 3.0f);
        const BodyId body = add_static(world, shapes[target], {random.next(-1, 1), random.next(-1, 1)}, target_angle);
        const float query_angle = shapes[query].type() == ShapeType::Box ? 0.0f : random.next(-3.0f, 3.0f);
        const Transform xf = at({random.next(-1.5f, 1.5f), random.next(-1.5f, 1.5f)}, query_angle);
        BodyId found[2];
        const int count = world.overlap_shape(shapes[query], xf, found, 2);
        const BodyView view = world.body(body);
        const bool narrow = collide(shapes[query], xf, *view.shape, view.transform).point_count > 0;
        ASSERT_EQ(count, narrow ? 1 : 0) << "query " << query << " target " << target << " trial " << trial;
        if (count == 1) {
          EXPECT_EQ(found[0], body);
        }
        const ShapeDistance distance = shape_distance(shapes[query], xf, *view.shape, view.transform);
        if (narrow) {
          float deepest = 0.0f;
          const Manifold m = collide(shapes[query], xf, *view.shape, view.transform);
          for (int i = 0; i < m.point_count; ++i) deepest = std::max(deepest, m.points[i].depth);
          if (deepest > 1e-4f) {
            EXPECT_EQ(distance.distance, 0.0f);
          }
          ++overlaps;
        } else {
          // Apart by the narrow phase: GJK finds a gap, unless they only just touch.
          if (collide(shapes[query], xf, *view.shape, view.transform, 1e-4f).point_count == 0) {
            EXPECT_GT(distance.distance, 0.0f);
          }
          ++apart;
        }
      }
    }
  }
  EXPECT_GT(overlaps, 500);
  EXPECT_GT(apart, 500);
}

// Overlaps come in slot order into the caller's buffer; the total counts them all.
TEST(OverlapQuery, SlotOrderCapacityAndFilter) {
  World world;
  std::vector<BodyId> ids;
  for (int i = 0; i < 10; ++i) {
    ids.push_back(add_static(world, make_circle(0.4f), {static_cast<float>(i) * 0.5f, 0.0f}, 0.0f,
                             i % 2 == 0 ? 1u : 2u));
  }
  BodyId found[4];
  EXPECT_EQ(world.overlap_shape(make_box({10.0f, 1.0f}), at({0.0f, 0.0f}), found, 4), 10);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(found[i], ids[static_cast<std::size_t>(i)]);
  QueryFilter odd;
  odd.layers = 2;
  odd.accept = [&ids](BodyId id) { return id != ids[1]; };
  EXPECT_EQ(world.overlap_shape(make_box({10.0f, 1.0f}), at({0.0f, 0.0f}), found, 4, odd), 4);
  EXPECT_EQ(found[0], ids[3]);
  EXPECT_EQ(found[3], ids[9]);
  EXPECT_THROW(world.overlap_shape(make_circle(1.0f), at({0.0f, 0.0f}), nullptr, 3), Error);
  EXPECT_EQ(world.overlap_shape(make_circle(1.0f), at({0.0f, 0.0f}), nullptr, 0), 3);
}

// Ray casts with a layer mask and a filter callback; sensors skipped unless asked for.
TEST(RayCastFilter, LayersCallbackAndSensors) {
  World world;
  const BodyId first = add_static(world, make_box({0.5f, 0.5f}), {2.0f, 0.0f}, 0.0f, 1);
  const BodyId second = add_static(world, make_circle(0.5f), {5.0f, 0.0f}, 0.0f, 2);
  const BodyId third = add_static(world, make_box({0.5f, 0.5f}), {8.0f, 0.0f}, 0.0f, 1);
  BodyDef sensor;
  sensor.type = BodyType::Static;
  sensor.is_sensor = true;
  sensor.position = {1.0f, 0.0f};
  const BodyId zone = world.create_body(sensor, make_box({0.2f, 0.2f}));
  QueryFilter all;
  auto hit = world.raycast_closest({0.0f, 0.0f}, {10.0f, 0.0f}, all);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->body, first);
  EXPECT_NEAR(hit->fraction, 0.15f, 1e-6f);
  all.include_sensors = true;
  EXPECT_EQ(world.raycast_closest({0.0f, 0.0f}, {10.0f, 0.0f}, all)->body, zone);
  QueryFilter layer_two;
  layer_two.layers = 2;
  hit = world.raycast_closest({0.0f, 0.0f}, {10.0f, 0.0f}, layer_two);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->body, second);
  EXPECT_NEAR(hit->fraction, 0.45f, 1e-6f);
  QueryFilter skip_first;
  skip_first.layers = 1;
  skip_first.accept = [first](BodyId id) { return id != first; };
  EXPECT_EQ(world.raycast_closest({0.0f, 0.0f}, {10.0f, 0.0f}, skip_first)->body, third);
}
