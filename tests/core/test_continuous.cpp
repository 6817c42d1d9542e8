// Continuous collision: a bullet cannot tunnel through a thin wall; without the sweep it does.
#include "core/collide/continuous.h"
#include "core/world.h"

#include <gtest/gtest.h>

using namespace impulse2d;

namespace {

// A 2 cm thick static wall at x = 5 and a 5 cm ball flying at it at `speed` m/s, no gravity.
struct BulletScene {
  World world;
  BodyId bullet;
  BulletScene(bool continuous, bool is_bullet, float speed) : world(make_settings(continuous)) {
    BodyDef wall;
    wall.type = BodyType::Static;
    wall.material = materials::static_ground();
    wall.position = {5.0f, 0.0f};
    world.create_body(wall, make_box({0.01f, 2.0f}));
    BodyDef def;
    def.is_bullet = is_bullet;
    def.material = materials::metal();
    def.linear_velocity = {speed, 0.0f};
    bullet = world.create_body(def, make_circle(0.05f));
  }
  static WorldSettings make_settings(bool continuous, float speculative_margin = 0.0f) {
    WorldSettings settings;
    settings.gravity = {0, 0};
    // The sweep is what stops bullets when speculative contacts are off (margin 0); with them
    // on, the contact is found a step ahead anyway (tested below).
    settings.speculative_margin = speculative_margin;
    settings.enable_continuous = continuous;
    return settings;
  }
};

}  // namespace

TEST(Continuous, WithoutTheSweepAFastBallTunnels) {
  BulletScene scene(false, true, 300.0f);  // 5 m per step: the wall is never seen overlapping
  for (int i = 0; i < 10; ++i) scene.world.step();
  EXPECT_GT(scene.world.body(scene.bullet).transform.position.x, 6.0f);
}

TEST(Continuous, ABulletIsStoppedAtTheWallAndBouncesBack) {
  for (float speed : {30.0f, 300.0f, 3000.0f}) {
    BulletScene scene(true, true, speed);
    bool hit = false;
    for (int i = 0; i < 60; ++i) {
      scene.world.step();
      hit = hit || scene.world.stats().bullets_moved_back > 0;
      // The ball's centre never gets past the wall's near face plus its radius.
      ASSERT_LT(scene.world.body(scene.bullet).transform.position.x, 5.0f) << "speed " << speed << " step " << i;
    }
    EXPECT_TRUE(hit);
    EXPECT_LT(scene.world.body(scene.bullet).linear_velocity.x, 0.0f) << "speed " << speed;
  }
}

TEST(Continuous, OnlyBodiesMarkedAsBulletsAreSwept) {
  BulletScene scene(true, false, 300.0f);
  for (int i = 0; i < 10; ++i) scene.world.step();
  EXPECT_GT(scene.world.body(scene.bullet).transform.position.x, 6.0f);
}

TEST(Continuous, SpeculativeContactsStopAFastBallWithoutTheSweep) {
  for (float speed : {30.0f, 300.0f, 3000.0f}) {
    BulletScene scene(false, false, speed);
    scene.world.set_settings(BulletScene::make_settings(false, 0.02f));
    for (int i = 0; i < 60; ++i) {
      scene.world.step();
      // Caught at the wall's near face (x = 4.99) minus the radius, never inside or past it.
      ASSERT_LT(scene.world.body(scene.bullet).transform.position.x, 4.99f - 0.05f + 1e-3f)
          << "speed " << speed << " step " << i;
    }
    EXPECT_LT(scene.world.body(scene.bullet).linear_velocity.x, 0.0f) << "speed " << speed;
  }
}

TEST(Continuous, SmallestExtentOfEachShape) {
  EXPECT_FLOAT_EQ(smallest_extent(make_circle(0.3f)), 0.3f);
  EXPECT_FLOAT_EQ(smallest_extent(make_box({0.5f, 0.2f})), 0.2f);
  EXPECT_NEAR(smallest_extent(make_oriented_box({0.5f, 0.2f})), 0.2f, 1e-6f);
}
