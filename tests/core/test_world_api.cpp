// World API: handles, removal, validation of bad input, forces and impulses.
#include "core/error.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace impulse2d;

namespace {
BodyDef dynamic_at(vec2 position) {
  BodyDef def;
  def.position = position;
  return def;
}
const float not_a_number = std::numeric_limits<float>::quiet_NaN();
const float infinity = std::numeric_limits<float>::infinity();
}  // namespace

TEST(Handles, StaleHandleIsAnErrorNotACrash) {
  World world;
  const BodyId first = world.create_body(dynamic_at({0, 0}), make_circle(0.5f));
  world.remove_body(first);
  EXPECT_FALSE(world.is_valid(first));
  EXPECT_THROW(world.body(first), Error);
  EXPECT_THROW(world.remove_body(first), Error);
  EXPECT_THROW(world.set_linear_velocity(first, {1, 0}), Error);
  EXPECT_THROW(world.body(BodyId{}), Error);
}

TEST(Handles, ReusedSlotGetsNewGeneration) {
  World world;
  const BodyId a = world.create_body(dynamic_at({0, 0}), make_circle(0.5f));
  const BodyId b = world.create_body(dynamic_at({2, 0}), make_circle(0.5f));
  world.remove_body(a);
  const BodyId c = world.create_body(dynamic_at({4, 0}), make_circle(0.5f));
  EXPECT_EQ(c.index, a.index);  // lowest free slot is reused
  EXPECT_NE(c.generation, a.generation);
  EXPECT_FALSE(world.is_valid(a));
  EXPECT_TRUE(world.is_valid(b));
  EXPECT_TRUE(world.is_valid(c));
  EXPECT_FLOAT_EQ(world.body(c).transform.position.x, 4.0f);
  EXPECT_EQ(world.body_count(), 2);
  const std::vector<BodyId> ids = world.body_ids();
  ASSERT_EQ(ids.size(), 2u);
  EXPECT_EQ(ids[0], c);  // ascending slot order
  EXPECT_EQ(ids[1], b);
}

TEST(Handles, RemovingABodyDropsItsContacts) {
  World world;
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  world.create_body(ground, make_box({5, 0.5f}));
  const BodyId ball = world.create_body(dynamic_at({0, 0.99f}), make_circle(0.5f));
  world.step();
  ASSERT_EQ(world.contacts().size(), 1u);
  world.remove_body(ball);
  EXPECT_TRUE(world.contacts().empty());
  world.step();  // must not touch the dead slot
  EXPECT_TRUE(world.contacts().empty());
}

TEST(Misuse, NonFiniteInputIsRejectedWithTheFieldNamed) {
  World world;
  BodyDef def;
  def.position = {not_a_number, 0};
  try {
    world.create_body(def, make_circle(1));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("position"), std::string::npos) << error.what();
  }
  def.position = {0, 0};
  def.linear_velocity = {0, infinity};
  EXPECT_THROW(world.create_body(def, make_circle(1)), Error);
  def.linear_velocity = {0, 0};
  def.material.density = -1;
  EXPECT_THROW(world.create_body(def, make_circle(1)), Error);
  def.material = materials::static_ground();  // density 0 cannot be dynamic
  EXPECT_THROW(world.create_body(def, make_circle(1)), Error);

  const BodyId body = world.create_body(BodyDef{}, make_circle(1));
  EXPECT_THROW(world.apply_force_to_center(body, {not_a_number, 0}), Error);
  EXPECT_THROW(world.apply_linear_impulse(body, {0, 0}, {infinity, 0}), Error);
  EXPECT_THROW(world.set_transform(body, {0, 0}, not_a_number), Error);
  EXPECT_THROW(world.advance(not_a_number), Error);
  EXPECT_EQ(world.body_count(), 1);  // nothing half-made
}

TEST(Misuse, InvalidSettingsNameTheField) {
  WorldSettings settings;
  settings.time_step = 0;
  try {
    World world(settings);
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("time_step"), std::string::npos);
  }
  World world;
  EXPECT_THROW(world.set_gravity({not_a_number, 0}), Error);
  EXPECT_FLOAT_EQ(world.settings().gravity.y, -9.81f);  // unchanged
}

TEST(Misuse, ShapeMadeByHandIsValidatedOnCreation) {
  World world;
  EXPECT_THROW(world.create_body(BodyDef{}, Circle{-1.0f}), Error);
  Polygon two_vertices;
  two_vertices.count = 2;
  EXPECT_THROW(world.create_body(BodyDef{}, two_vertices), Error);
}

TEST(Misuse, DivergedBodyIsReportedAndRestored) {
  WorldSettings settings;
  settings.max_linear_speed = std::numeric_limits<float>::max();
  World world(settings);
  const BodyId body = world.create_body(dynamic_at({1, 2}), make_circle(0.5f));
  world.apply_force_to_center(body, {std::numeric_limits<float>::max(), 0});
  world.apply_force_to_center(body, {std::numeric_limits<float>::max(), 0});  // overflows to inf
  world.step();
  ASSERT_EQ(world.diverged_bodies().size(), 1u);
  EXPECT_EQ(world.diverged_bodies()[0], body);
  EXPECT_FLOAT_EQ(world.body(body).transform.position.x, 1.0f);
  EXPECT_TRUE(std::isfinite(world.body(body).linear_velocity.x));
}

TEST(Materials, SetMaterialChangesMassAndFrictionAndValidates) {
  World world;
  BodyDef def;
  def.material = materials::wood();
  const BodyId body = world.create_body(def, make_circle(0.5f));
  const float wood_mass = world.body(body).mass;
  Material heavy = materials::metal();  // density 1.2 vs wood's 0.3
  world.set_material(body, heavy);
  EXPECT_FLOAT_EQ(world.body(body).mass, wood_mass * 4.0f);
  EXPECT_FLOAT_EQ(world.body(body).inverse_inertia,
                  1.0f / (0.5f * world.body(body).mass * 0.25f));
  EXPECT_EQ(world.body(body).material->name, "Metal");
  heavy.static_friction = 0.1f;  // below dynamic: invalid
  EXPECT_THROW(world.set_material(body, heavy), Error);
  EXPECT_THROW(world.set_material(body, materials::static_ground()), Error);  // density 0
  EXPECT_EQ(world.body(body).material->name, "Metal");  // unchanged by the failed calls
}

TEST(Forces, AngularImpulseChangesSpinByRCrossJOverI) {
  World world(WorldSettings{});
  BodyDef def;
  def.material.density = 2.0f;
  const BodyId body = world.create_body(def, make_circle(0.5f));
  const vec2 impulse{0.0f, 3.0f};
  const vec2 point{0.5f, 0.0f};  // r = (0.5, 0): r x J = 1.5
  world.apply_linear_impulse(body, impulse, point);
  const BodyView b = world.body(body);
  const float inertia = 0.5f * b.mass * 0.25f;
  EXPECT_NEAR(b.angular_velocity, 1.5f / inertia, 1e-5f * 1.5f / inertia);
  EXPECT_NEAR(b.linear_velocity.y, 3.0f / b.mass, 1e-6f);
}

TEST(Forces, ForcesAreClearedAfterTheStep) {
  WorldSettings settings;
  settings.gravity = {0, 0};
  World world(settings);
  const BodyId body = world.create_body(BodyDef{}, make_circle(0.5f));
  world.apply_force_to_center(body, {10, 0});
  world.step();
  const float after_one = world.body(body).linear_velocity.x;
  EXPECT_NEAR(after_one, 10.0f / world.body(body).mass * settings.time_step, 1e-6f);
  world.step();
  EXPECT_FLOAT_EQ(world.body(body).linear_velocity.x, after_one);
}

TEST(Accumulator, TakesWholeStepsAndInterpolatesTheRemainder) {
  WorldSettings settings;
  settings.time_step = 0.01f;
  settings.gravity = {0, 0};
  World world(settings);
  BodyDef def;
  def.linear_velocity = {1.0f, 0.0f};
  const BodyId body = world.create_body(def, make_circle(0.5f));
  EXPECT_EQ(world.advance(0.025f), 2);
  EXPECT_NEAR(world.interpolation_alpha(), 0.5f, 1e-4f);
  EXPECT_EQ(world.advance(1.0f), 25);  // clamped to 0.25 s: 0.255 s / 0.01 = 25 steps
  // Drawing interpolates previous * (1 - alpha) + current * alpha (not the swapped weights).
  struct Recorder : DebugDraw {
    vec2 center{0};
    void draw_solid_polygon(const vec2*, int, Color, Color) override {}
    void draw_solid_circle(vec2 c, float, vec2, Color, Color) override { center = c; }
    void draw_segment(vec2, vec2, Color) override {}
    void draw_arrow(vec2, vec2, Color) override {}
    void draw_point(vec2, float, Color) override {}
    void draw_text(vec2, const std::string&, Color) override {}
  } recorder;
  DebugDrawOptions options;
  options.interpolation_alpha = 0.25f;
  world.draw(recorder, options);
  const BodyView b = world.body(body);
  EXPECT_NEAR(recorder.center.x, b.previous_position.x * 0.75f + b.transform.position.x * 0.25f, 1e-6f);
  EXPECT_LT(recorder.center.x, b.transform.position.x);
}

TEST(Layers, BodiesWithoutACommonLayerPassThrough) {
  World world;
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.collision_layers = 0b01;
  world.create_body(ground, make_box({5, 0.5f}));
  BodyDef ghost = dynamic_at({0, 2});
  ghost.collision_layers = 0b10;
  const BodyId body = world.create_body(ghost, make_circle(0.5f));
  for (int i = 0; i < 120; ++i) world.step();
  EXPECT_LT(world.body(body).transform.position.y, -1.0f);
}
