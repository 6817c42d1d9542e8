// Queries: AABB, point and ray casts with exact answers and stable order.
#include "core/world.h"

#include <gtest/gtest.h>

using namespace impulse2d;

namespace {
struct QueryScene {
  World world;
  BodyId circle, box, triangle;
  QueryScene() {
    BodyDef def;
    def.type = BodyType::Static;
    def.material = materials::static_ground();
    def.position = {0, 0};
    circle = world.create_body(def, make_circle(1.0f));
    def.position = {5, 0};
    box = world.create_body(def, make_box({1.0f, 2.0f}));
    def.position = {10, 0};
    const vec2 square[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    triangle = world.create_body(def, make_polygon(square, 4));
  }
};
}  // namespace

TEST(Queries, AabbFindsOverlappingBodiesInSlotOrder) {
  QueryScene scene;
  std::vector<BodyId> found;
  scene.world.query_aabb(Aabb{{0.5f, -0.1f}, {4.5f, 0.1f}}, [&](BodyId id) {
    found.push_back(id);
    return true;
  });
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0], scene.circle);
  EXPECT_EQ(found[1], scene.box);
  found.clear();
  scene.world.query_aabb(Aabb{{-20, -20}, {20, 20}}, [&](BodyId id) {
    found.push_back(id);
    return false;  // stop after the first
  });
  EXPECT_EQ(found.size(), 1u);
}

TEST(Queries, PointInsideShapesOnly) {
  QueryScene scene;
  std::vector<BodyId> found;
  auto collect = [&](BodyId id) {
    found.push_back(id);
    return true;
  };
  scene.world.query_point({0.7f, 0.7f}, collect);  // inside the circle (0.98 < 1)
  scene.world.query_point({0.8f, 0.8f}, collect);  // inside its AABB, outside the circle
  scene.world.query_point({5.9f, 1.9f}, collect);  // inside the box
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0], scene.circle);
  EXPECT_EQ(found[1], scene.box);
}

TEST(Queries, RaycastClosestAndAllWithExactFractions) {
  QueryScene scene;
  const vec2 origin{-5, 0};
  const vec2 translation{20, 0};
  const std::optional<RayHit> closest = scene.world.raycast_closest(origin, translation);
  ASSERT_TRUE(closest.has_value());
  EXPECT_EQ(closest->body, scene.circle);
  EXPECT_NEAR(closest->fraction, 4.0f / 20.0f, 1e-6f);
  EXPECT_NEAR(closest->point.x, -1.0f, 1e-5f);
  EXPECT_NEAR(closest->normal.x, -1.0f, 1e-6f);
  const std::vector<RayHit> all = scene.world.raycast_all(origin, translation);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[1].body, scene.box);
  EXPECT_NEAR(all[1].fraction, 9.0f / 20.0f, 1e-6f);
  EXPECT_EQ(all[2].body, scene.triangle);
  EXPECT_NEAR(all[2].fraction, 14.0f / 20.0f, 1e-6f);
  EXPECT_FALSE(scene.world.raycast_closest({-5, 5}, {20, 0}).has_value());
  EXPECT_FALSE(scene.world.raycast_closest(origin, translation, 0u).has_value());  // no layer
}
