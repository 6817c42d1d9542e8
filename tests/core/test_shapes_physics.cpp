/// @file test_shapes_physics.cpp
/// Capsules, segments and rounded polygons in the world, default settings, against exact
/// answers (issue 31): a lying capsule rests at height r and on a slope holds below
/// tan(theta) = mu_s and slides at g (sin(theta) - mu_d cos(theta)); a rounded polygon rests
/// at its height plus its rounding; segments are level geometry only; snapshots keep them.

#include "core/error.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace impulse2d {
namespace {

constexpr float g = 9.81f;
constexpr float pi = 3.14159265358979f;

Material surface(float static_friction, float dynamic_friction) {
  return Material{"Surface", 1.0f, 0.0f, static_friction, dynamic_friction};
}

/// A static box whose top face is y = 0 (20 m wide).
void add_ground(World& world, const Material& material) {
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = material;
  ground.material.density = 0.0f;
  ground.position = {0.0f, -0.5f};
  world.create_body(ground, make_box({10.0f, 0.5f}));
}

/// Runs `seconds` of steps.
void run(World& world, float seconds) {
  const int steps = static_cast<int>(std::lround(seconds / world.settings().time_step));
  for (int i = 0; i < steps; ++i) world.step();
}

// The soft step lets a resting contact sit a little into the surface: the settled overlap of
// a box resting on the same ground, measured with the same settings, is the allowance.
float box_rest_overlap() {
  World world;
  add_ground(world, surface(0.6f, 0.5f));
  BodyDef box;
  box.material = surface(0.6f, 0.5f);
  box.position = {0.0f, 0.25f};
  const BodyId id = world.create_body(box, make_oriented_box({0.5f, 0.25f}));
  run(world, 3.0f);
  return 0.25f - world.body(id).transform.position.y;
}

TEST(CapsulePhysics, LyingCapsuleRestsAtHeightR) {
  const float radius = 0.25f;
  World world;
  add_ground(world, surface(0.6f, 0.5f));
  BodyDef def;
  def.material = surface(0.6f, 0.5f);
  def.position = {0.0f, radius + 0.2f};  // dropped from 20 cm
  const BodyId capsule = world.create_body(def, make_capsule({-0.5f, 0.0f}, {0.5f, 0.0f}, radius));
  run(world, 3.0f);
  const BodyView body = world.body(capsule);
  const float overlap = box_rest_overlap();
  EXPECT_NEAR(body.transform.position.y, radius - overlap, 1e-4f) << "box overlap " << overlap;
  EXPECT_LT(std::fabs(body.transform.position.y - radius), world.settings().slop);
  EXPECT_NEAR(body.angle, 0.0f, 1e-4f);  // still lying flat
  EXPECT_LT(std::fabs(body.linear_velocity.y), 1e-4f);
}

// A capsule stood on end, tipped by 0.05 rad, topples and comes to rest lying at height r; its
// energy (kinetic plus potential, above the lying rest) never grows beyond the start's.
TEST(CapsulePhysics, StoodOnEndTopplesAndComesToRestLying) {
  const float radius = 0.2f, half_length = 0.6f;
  World world;
  add_ground(world, surface(0.6f, 0.5f));
  BodyDef def;
  def.material = surface(0.6f, 0.5f);
  def.angle = 0.05f;
  def.position = {-std::sin(0.05f) * (half_length + radius), std::cos(0.05f) * (half_length + radius)};
  const BodyId id = world.create_body(def, make_capsule({0.0f, -half_length}, {0.0f, half_length}, radius));
  auto energy = [&] {
    const BodyView body = world.body(id);
    return 0.5f * body.mass * length_squared(body.linear_velocity) +
           0.5f * body.inertia * body.angular_velocity * body.angular_velocity +
           body.mass * g * (body.transform.position.y - radius);
  };
  const float start = energy();
  float highest = start;
  for (int i = 0; i < 300; ++i) {
    world.step();
    highest = std::max(highest, energy());
  }
  EXPECT_LE(highest, start * 1.001f);
  const BodyView body = world.body(id);
  EXPECT_NEAR(std::fabs(std::remainder(body.angle, pi)), 0.5f * pi, 1e-3f);  // lying
  EXPECT_NEAR(body.transform.position.y, radius, world.settings().slop);
  EXPECT_LT(std::sqrt(length_squared(body.linear_velocity)), 1e-3f);
  EXPECT_LT(std::fabs(body.angular_velocity), 1e-3f);
}

// A static slab tilted by theta whose top face passes through the origin, and a capsule lying
// on it along the slope.
BodyId capsule_on_incline(World& world, float theta, const Material& material, float radius) {
  const vec2 up_normal{-std::sin(theta), std::cos(theta)};
  BodyDef slab;
  slab.type = BodyType::Static;
  slab.material = material;
  slab.material.density = 0.0f;
  slab.angle = theta;
  slab.position = up_normal * -0.5f;
  world.create_body(slab, make_oriented_box({20.0f, 0.5f}));
  BodyDef body;
  body.material = material;
  body.angle = theta;
  body.position = up_normal * radius;
  return world.create_body(body, make_capsule({-0.5f, 0.0f}, {0.5f, 0.0f}, radius));
}

float down_slope(vec2 v, float theta) { return glm::dot(v, vec2(-std::cos(theta), -std::sin(theta))); }

TEST(CapsulePhysics, OnASlopeHoldsBelowTheFrictionAngle) {
  const float mu_s = 0.5f;
  const float theta = std::atan(mu_s) - 0.02f;
  World world;
  const BodyId capsule = capsule_on_incline(world, theta, surface(mu_s, 0.4f), 0.25f);
  const vec2 start = world.body(capsule).transform.position;
  run(world, 2.0f);
  EXPECT_LT(std::fabs(down_slope(world.body(capsule).transform.position - start, theta)),
            world.settings().slop);
  EXPECT_LT(std::fabs(down_slope(world.body(capsule).linear_velocity, theta)), 1e-3f);
}

TEST(CapsulePhysics, OnASlopeSlidesAtTheDynamicFrictionAcceleration) {
  const float mu_s = 0.5f, mu_d = 0.3f;
  const float theta = std::atan(mu_s) + 0.02f;
  World world;
  const BodyId capsule = capsule_on_incline(world, theta, surface(mu_s, mu_d), 0.25f);
  run(world, 0.5f);
  const float v1 = down_slope(world.body(capsule).linear_velocity, theta);
  run(world, 1.0f);
  const float v2 = down_slope(world.body(capsule).linear_velocity, theta);
  const float measured = (v2 - v1) / 1.0f;
  const float expected = g * (std::sin(theta) - mu_d * std::cos(theta));
  EXPECT_NEAR(measured, expected, 0.01f * expected) << "measured " << measured;
  EXPECT_NEAR(world.body(capsule).angular_velocity, 0.0f, 1e-3f);  // slides, does not roll
}

TEST(RoundedPolygonPhysics, RestsAtItsHeightPlusTheRounding) {
  const float rounding = 0.1f;
  const vec2 box[4] = {{-0.5f, -0.25f}, {0.5f, -0.25f}, {0.5f, 0.25f}, {-0.5f, 0.25f}};
  World world;
  add_ground(world, surface(0.6f, 0.5f));
  BodyDef def;
  def.material = surface(0.6f, 0.5f);
  def.position = {0.0f, 0.25f + rounding + 0.1f};
  const BodyId id = world.create_body(def, make_rounded_polygon(box, 4, rounding));
  run(world, 3.0f);
  const float overlap = box_rest_overlap();
  EXPECT_NEAR(world.body(id).transform.position.y, 0.25f + rounding - overlap, 1e-4f);
  EXPECT_NEAR(world.body(id).angle, 0.0f, 1e-4f);
}

TEST(SegmentPhysics, OnlyStaticOrKinematicBodiesMayBeSegments) {
  World world;
  BodyDef def;
  try {
    world.create_body(def, make_segment({-1.0f, 0.0f}, {1.0f, 0.0f}));
    ADD_FAILURE() << "a dynamic segment was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("segment"), std::string::npos) << error.what();
  }
  EXPECT_EQ(world.body_count(), 0);
  def.type = BodyType::Kinematic;
  EXPECT_NO_THROW(world.create_body(def, make_segment({-1.0f, 0.0f}, {1.0f, 0.0f})));
}

TEST(SegmentPhysics, BoxAndBallRestOnASegmentFloor) {
  World world;
  BodyDef floor;
  floor.type = BodyType::Static;
  floor.material = surface(0.6f, 0.5f);
  floor.material.density = 0.0f;
  world.create_body(floor, make_segment({-10.0f, 0.0f}, {10.0f, 0.0f}));
  BodyDef def;
  def.material = surface(0.6f, 0.5f);
  def.position = {-2.0f, 0.4f};
  const BodyId box = world.create_body(def, make_oriented_box({0.5f, 0.25f}));
  def.position = {2.0f, 0.6f};
  const BodyId ball = world.create_body(def, make_circle(0.5f));
  def.position = {0.0f, 0.4f};
  const BodyId capsule = world.create_body(def, make_capsule({-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f));
  run(world, 3.0f);
  const float overlap = box_rest_overlap();
  EXPECT_NEAR(world.body(box).transform.position.y, 0.25f - overlap, 1e-4f);
  EXPECT_NEAR(world.body(ball).transform.position.y, 0.5f - overlap, 1e-3f);
  EXPECT_NEAR(world.body(capsule).transform.position.y, 0.25f - overlap, 1e-4f);
}

TEST(NewShapesSnapshot, RestoredWorldContinuesBitForBit) {
  World world;
  add_ground(world, surface(0.6f, 0.5f));
  BodyDef def;
  def.material = surface(0.6f, 0.5f);
  def.type = BodyType::Static;
  world.create_body(def, make_segment({-3.0f, 1.0f}, {3.0f, 2.0f}));
  def.type = BodyType::Dynamic;
  const vec2 pentagon[5] = {{0.6f, -0.45f}, {0.75f, 0.25f}, {0.0f, 0.65f}, {-0.75f, 0.25f}, {-0.6f, -0.45f}};
  for (int i = 0; i < 6; ++i) {
    def.position = {-2.5f + static_cast<float>(i), 4.0f + 0.7f * static_cast<float>(i)};
    def.angle = 0.3f * static_cast<float>(i);
    world.create_body(def, i % 2 == 0 ? make_capsule({-0.4f, 0.0f}, {0.4f, 0.0f}, 0.2f)
                                      : make_rounded_polygon(pentagon, 5, 0.05f * static_cast<float>(i)));
  }
  run(world, 1.0f);
  World restored;
  restored.restore_snapshot(world.save_snapshot());
  EXPECT_EQ(restored.state_hash(), world.state_hash());
  for (int i = 0; i < 90; ++i) {
    world.step();
    restored.step();
  }
  EXPECT_EQ(restored.state_hash(), world.state_hash());
}

// World queries over the new shapes: a ray stops on a capsule's cap and on a segment; a
// capsule overlaps a segment floor; a rounded box cast down meets the floor at its rounding.
TEST(NewShapesQueries, RaysOverlapsAndCasts) {
  World world;
  BodyDef def;
  def.type = BodyType::Static;
  const BodyId floor = world.create_body(def, make_segment({-10.0f, 0.0f}, {10.0f, 0.0f}));
  def.position = {3.0f, 2.0f};
  const BodyId capsule = world.create_body(def, make_capsule({-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f));
  const std::optional<RayHit> cap = world.raycast_closest({6.0f, 2.0f}, {-6.0f, 0.0f}, QueryFilter{});
  ASSERT_TRUE(cap.has_value());
  EXPECT_EQ(cap->body, capsule);
  EXPECT_NEAR(cap->point.x, 4.5f, 1e-5f);
  const std::optional<RayHit> down = world.raycast_closest({-2.0f, 3.0f}, {0.0f, -6.0f}, QueryFilter{});
  ASSERT_TRUE(down.has_value());
  EXPECT_EQ(down->body, floor);
  EXPECT_NEAR(down->fraction, 0.5f, 1e-6f);
  EXPECT_NEAR(down->normal.y, 1.0f, 1e-6f);
  BodyId found[4];
  const Shape probe = make_capsule({-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f);
  ASSERT_EQ(world.overlap_shape(probe, Transform{{-3.0f, 0.2f}, Rotation{}}, found, 4), 1);
  EXPECT_EQ(found[0], floor);
  EXPECT_EQ(world.overlap_shape(probe, Transform{{-3.0f, 0.3f}, Rotation{}}, found, 4), 0);
  const vec2 box[4] = {{-0.5f, -0.25f}, {0.5f, -0.25f}, {0.5f, 0.25f}, {-0.5f, 0.25f}};
  const std::optional<ShapeCastHit> cast =
      world.cast_shape(make_rounded_polygon(box, 4, 0.1f), Transform{{-4.0f, 2.0f}, Rotation{}}, {0.0f, -3.0f});
  ASSERT_TRUE(cast.has_value());
  EXPECT_EQ(cast->body, floor);
  // The rounded bottom (0.25 + 0.1 below the centre) meets y = 0 after 2 - 0.35 = 1.65 m.
  EXPECT_NEAR(cast->fraction, 1.65f / 3.0f, 1e-5f);
}

}  // namespace
}  // namespace impulse2d
