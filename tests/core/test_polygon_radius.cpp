// The radius each made polygon caches (Polygon::radius) must equal the one computed from its
// vertices, and a world stepping hand-made polygons (radius unknown, computed on use) must stay
// bit-identical to one stepping the same polygons made by make_polygon; `create_body` makes the
// radius itself, so a stale one passed in cannot steer the step.

#include "core/solver/world_state.h"
#include "core/collide.h"
#include "core/collide/speculative_reach.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace impulse2d {
namespace {

Shape hexagon(float size) {
  std::vector<vec2> vertices;
  for (int i = 0; i < 6; ++i) {
    const float angle = 1.0471976f * static_cast<float>(i);
    vertices.push_back(vec2(size * std::cos(angle) + 0.3f, size * 0.7f * std::sin(angle)));
  }
  return make_polygon(vertices.data(), static_cast<int>(vertices.size()));
}

// Tumbling polygons on a slope, each shape's cached radius first set to `forced_radius` (NaN:
// left as made): recycled contacts whose recycling depends on the extents, and rotating
// bodies whose speculative reach does.
World world_with_radius(float forced_radius) {
  WorldSettings settings;
  settings.solver = SolverMethod::SoftStep;
  World world(settings);
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.angle = -0.3f;
  world.create_body(ground, make_oriented_box({20.0f, 0.5f}));
  for (int i = 0; i < 12; ++i) {
    BodyDef def;
    def.position = {-6.0f + static_cast<float>(i % 4) * 1.5f, 2.0f + static_cast<float>(i / 4) * 1.5f};
    def.angular_velocity = 0.5f * static_cast<float>(i % 3);
    Shape shape = i % 2 == 0 ? hexagon(0.5f + 0.05f * static_cast<float>(i)) : make_oriented_box({0.4f, 0.3f});
    if (!std::isnan(forced_radius)) {
      Polygon polygon = shape.polygon();
      polygon.radius = forced_radius;
      shape = polygon;
    }
    world.create_body(def, shape);
  }
  return world;
}

std::uint64_t tumble_hash(float forced_radius, int steps) {
  World world = world_with_radius(forced_radius);
  for (int s = 0; s < steps; ++s) world.step();
  return world.state_hash();
}

TEST(PolygonRadius, MadePolygonsCacheTheirFarthestVertexDistance) {
  for (float size : {0.01f, 0.5f, 3.0f, 250.0f}) {
    const Shape shape = hexagon(size);
    EXPECT_EQ(shape.polygon().radius, farthest_vertex_distance(shape.polygon())) << size;
    EXPECT_GT(shape.polygon().radius, 0.0f);
  }
  const vec2 triangle[3] = {{0.0f, 0.0f}, {4.0f, 0.0f}, {0.0f, 1.0f}};
  const Shape made = make_polygon(triangle, 3);
  EXPECT_EQ(made.polygon().radius, farthest_vertex_distance(made.polygon()));
  const Shape box = make_oriented_box({2.0f, 0.25f});
  EXPECT_EQ(box.polygon().radius, farthest_vertex_distance(box.polygon()));
  EXPECT_FLOAT_EQ(box.polygon().radius, std::sqrt(4.0f + 0.0625f));
}

TEST(PolygonRadius, HandMadePolygonComputesItsRadius) {
  Polygon polygon = box_as_polygon(Box{{3.0f, 4.0f}});
  EXPECT_LT(polygon.radius, 0.0f);  // unknown: not made by make_polygon
  EXPECT_EQ(polygon_radius(polygon), 5.0f);
  polygon.radius = 7.0f;
  EXPECT_EQ(polygon_radius(polygon), 7.0f);  // a known radius is used as is
}

TEST(PolygonRadius, CreateBodyReplacesAStaleRadius) {
  const float unknown = -1.0f;  // every polygon's radius computed from its vertices
  const float made = std::nanf("");  // radii as make_polygon / make_oriented_box cached them
  const float stale = 0.0f;  // e.g. vertices edited after make_polygon
  EXPECT_EQ(tumble_hash(made, 240), tumble_hash(unknown, 240));
  EXPECT_EQ(tumble_hash(stale, 240), tumble_hash(made, 240));
  EXPECT_EQ(WorldState::of(world_with_radius(stale)).bodies[1].shape.polygon().radius,
            farthest_vertex_distance(WorldState::of(world_with_radius(made)).bodies[1].shape.polygon()));
}

TEST(PolygonRadius, TheRadiusSteersTheSpeculativeReach) {
  // The equalities above are a real check: a wrong radius would change the step (here the
  // speculative reach of a spinning polygon, read through polygon_radius).
  const World world = world_with_radius(std::nanf(""));
  std::vector<Body> bodies = WorldState::of(world).bodies;
  bodies[1].angular_velocity = 10.0f;
  const std::vector<std::uint8_t> alive(bodies.size(), 1);
  std::vector<float> right, wrong;
  compute_speculative_reach(bodies, alive, world.settings(), 1.0f / 60.0f, right);
  Polygon no_radius = bodies[1].shape.polygon();
  no_radius.radius = 0.0f;
  bodies[1].shape = no_radius;
  compute_speculative_reach(bodies, alive, world.settings(), 1.0f / 60.0f, wrong);
  EXPECT_GT(right[1], wrong[1]);
}

}  // namespace
}  // namespace impulse2d
