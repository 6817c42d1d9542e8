// Resting contact: a box on the ground and a 10-box stack must not drift (accumulated
// impulses with warm starting). "Drift" is measured against the settled pose after one
// second, and must stay below the slop, the overlap the solver is allowed to keep.
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace impulse2d;

namespace {

BodyId build_stack(World& world, int boxes, const Shape& shape, float half_height) {
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0, -0.5f};
  world.create_body(ground, make_box({20, 0.5f}));
  BodyId top;
  for (int i = 0; i < boxes; ++i) {
    BodyDef def;
    def.material = materials::wood();
    def.position = {0, half_height + 2 * half_height * static_cast<float>(i)};
    top = world.create_body(def, shape);
  }
  return top;
}

}  // namespace

TEST(Stacking, RestingBoxDoesNotDrift) {
  World world;
  const BodyId box = build_stack(world, 1, make_oriented_box({0.5f, 0.5f}), 0.5f);
  for (int i = 0; i < 60; ++i) world.step();
  const vec2 settled = world.body(box).transform.position;
  for (int i = 0; i < 600; ++i) world.step();
  const BodyView body = world.body(box);
  EXPECT_LT(glm::length(body.transform.position - settled), world.settings().slop);
  EXPECT_LT(std::fabs(body.angle), 1e-3f);
  EXPECT_GT(body.transform.position.y, 0.5f - world.settings().slop);
}

TEST(Stacking, TenBoxStackDoesNotDriftWithAccumulated) {
  World world;
  const BodyId top = build_stack(world, 10, make_oriented_box({0.5f, 0.5f}), 0.5f);
  for (int i = 0; i < 60; ++i) world.step();
  const vec2 settled = world.body(top).transform.position;
  // Each of the 10 contacts may keep `slop` of overlap plus one step of gravity's travel
  // (g dt^2) that position correction has not yet removed: that much sinking, and no more.
  const float dt = world.settings().time_step;
  EXPECT_GT(settled.y, 9.5f - 10 * (world.settings().slop + 9.81f * dt * dt));
  for (int i = 0; i < 600; ++i) world.step();
  EXPECT_LT(glm::length(world.body(top).transform.position - settled), world.settings().slop);
  EXPECT_LT(std::fabs(world.body(top).angle), 1e-2f);
}

TEST(Stacking, AxisAlignedStackDoesNotDrift) {
  World world;
  const BodyId top = build_stack(world, 10, make_box({0.5f, 0.5f}), 0.5f);
  for (int i = 0; i < 60; ++i) world.step();
  const vec2 settled = world.body(top).transform.position;
  for (int i = 0; i < 600; ++i) world.step();
  EXPECT_LT(glm::length(world.body(top).transform.position - settled), world.settings().slop);
}

TEST(Sleeping, ARestingStackFallsAsleepAndWakesWhenHit) {
  WorldSettings settings;
  settings.enable_sleeping = true;
  World world(settings);
  const BodyId top = build_stack(world, 3, make_oriented_box({0.5f, 0.5f}), 0.5f);
  for (int i = 0; i < 180; ++i) world.step();
  EXPECT_FALSE(world.body(top).awake);
  EXPECT_EQ(world.stats().awake_body_count, 0);
  BodyDef ball;
  ball.position = {0, 4.0f};
  ball.linear_velocity = {0, -5};
  world.create_body(ball, make_circle(0.25f));
  for (int i = 0; i < 20; ++i) world.step();
  EXPECT_TRUE(world.body(top).awake);
}

TEST(Sleeping, AMovingKinematicBodyWakesWhatItPushes) {
  WorldSettings settings;
  settings.enable_sleeping = true;
  World world(settings);
  const BodyId box = build_stack(world, 1, make_oriented_box({0.5f, 0.5f}), 0.5f);
  for (int i = 0; i < 120; ++i) world.step();
  ASSERT_FALSE(world.body(box).awake);
  BodyDef pusher;
  pusher.type = BodyType::Kinematic;
  pusher.position = {-1.2f, 0.5f};
  pusher.linear_velocity = {1.0f, 0.0f};
  world.create_body(pusher, make_box({0.5f, 0.4f}));
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_TRUE(world.body(box).awake);
  EXPECT_GT(world.body(box).transform.position.x, 0.5f);  // pushed along, not overlapped
}
