/// @file test_compound.cpp
/// Compound bodies (several shapes on one body, issue 31) at the default settings: mass, centre
/// of mass and inertia are the analytic sums; a compound of one shape steps bit for bit as the
/// plain body; a box split into two halves follows the whole box; a T stands on its stem; each
/// shape keeps its own material and layers; events, queries and snapshots name the shape; bad
/// input is refused naming the shape.

#include "core/error.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace impulse2d {
namespace {

/// Rough and inelastic.
Material rough() { return Material{"Rough", 1.0f, 0.0f, 0.8f, 0.6f}; }
/// Frictionless and inelastic.
Material ice() { return Material{"Ice", 1.0f, 0.0f, 0.0f, 0.0f}; }

ShapeDef part(const Shape& shape, vec2 position, float angle = 0.0f, Material material = rough()) {
  ShapeDef def;
  def.shape = shape;
  def.position = position;
  def.angle = angle;
  def.material = material;
  return def;
}

/// A static ground box whose top face is y = 0, 40 m wide.
BodyId add_ground(World& world, const Material& material = rough()) {
  BodyDef def;
  def.type = BodyType::Static;
  def.position = {0.0f, -0.5f};
  def.material = material;
  return world.create_body(def, make_box({20.0f, 0.5f}));
}

/// Float's relative precision: sums of a few products are exact to a few of these.
constexpr float epsilon = 1.1920929e-7f;

TEST(Compound, LShapeMassCentreAndInertiaAreTheAnalyticSums) {
  // Three unit squares at (0,0), (1,0) and (0,1), density 2: mass 6, centre (1/3, 1/3); each
  // square's own inertia m (w^2 + h^2) / 12 = 1/3, plus m d^2 over the offsets from the centre:
  // 2 (2/9 + 5/9 + 5/9) = 8/3; in all 11/3 kg m^2.
  Material dense = rough();
  dense.density = 2.0f;
  const Shape square = make_oriented_box({0.5f, 0.5f});
  const ShapeDef shapes[] = {part(square, {0, 0}, 0, dense), part(square, {1, 0}, 0, dense),
                             part(square, {0, 1}, 0, dense)};
  World world;
  BodyDef def;
  def.position = {10.0f, 5.0f};
  const BodyView view = world.body(world.create_body(def, shapes, 3));
  EXPECT_NEAR(view.mass, 6.0f, 6.0f * 4 * epsilon);
  EXPECT_NEAR(view.inertia, 11.0f / 3.0f, 11.0f / 3.0f * 1e-6f);
  // The body's origin moved to the centre of mass; its shapes moved the other way.
  EXPECT_NEAR(view.transform.position.x, 10.0f + 1.0f / 3.0f, 10.0f * 4 * epsilon);
  EXPECT_NEAR(view.transform.position.y, 5.0f + 1.0f / 3.0f, 5.0f * 4 * epsilon);
  ASSERT_EQ(view.shape_count, 3);
  EXPECT_NEAR(view.shapes[1].local.position.x, 2.0f / 3.0f, 4 * epsilon);
  EXPECT_NEAR(view.shapes[1].local.position.y, -1.0f / 3.0f, 4 * epsilon);
}

TEST(Compound, TurnedShapesAndDensitiesCountInTheSums) {
  // A disc of density 3 and radius 0.5 at (-1, 0) and a 2 x 0.5 bar of density 1 turned 90
  // degrees at (1, 0): masses 3 pi / 4 and 1, the centre between them by the lever rule.
  Material heavy = rough();
  heavy.density = 3.0f;
  const float pi = 3.14159265f;
  const ShapeDef shapes[] = {part(make_circle(0.5f), {-1, 0}, 0, heavy),
                             part(make_oriented_box({1.0f, 0.25f}), {1, 0}, 0.5f * pi)};
  World world;
  const BodyView view = world.body(world.create_body(BodyDef{}, shapes, 2));
  const float disc_mass = 3.0f * pi * 0.25f;
  const float mass = disc_mass + 1.0f;
  const float centre_x = (-disc_mass + 1.0f) / mass;
  const float inertia = disc_mass * 0.25f / 2.0f + disc_mass * (1.0f + centre_x) * (1.0f + centre_x) +
                        1.0f * (4.0f + 0.25f) / 12.0f + 1.0f * (1.0f - centre_x) * (1.0f - centre_x);
  EXPECT_NEAR(view.mass, mass, mass * 1e-6f);
  EXPECT_NEAR(view.transform.position.x, centre_x, 1e-6f);
  EXPECT_NEAR(view.transform.position.y, 0.0f, 1e-6f);
  EXPECT_NEAR(view.inertia, inertia, inertia * 1e-6f);
  // The bar turned: its bounds are 0.5 wide and 2 tall.
  EXPECT_NEAR(view.aabb.upper.y, 1.0f, 1e-6f);
  EXPECT_NEAR(view.aabb.upper.x, 1.25f, 1e-6f);
}

/// Drops and pushes the body made by `make` onto rough ground; returns the world after
/// `steps` steps (with recycling off when asked).
template <class Make>
World run_body(Make make, int steps, bool recycling = true) {
  WorldSettings settings;
  if (!recycling) settings.contact_recycle_distance = 0.0f;
  World world(settings);
  add_ground(world);
  make(world);
  for (int i = 0; i < steps; ++i) world.step();
  return world;
}

TEST(Compound, OneShapeAtItsOriginStepsBitForBitAsThePlainBody) {
  // The same collide calls, the same anchors, the same recycling: the same state, at the
  // default settings and with every manifold found afresh.
  BodyDef def;
  def.position = {0.0f, 1.0f};
  def.angle = 0.3f;
  def.linear_velocity = {2.0f, 0.0f};
  def.angular_velocity = 1.0f;
  def.material = rough();
  for (const Shape& shape : {make_oriented_box({0.5f, 0.25f}), make_circle(0.4f),
                             make_capsule({-0.4f, 0.0f}, {0.4f, 0.0f}, 0.2f)}) {
    for (const bool recycling : {true, false}) {
      const World plain = run_body([&](World& w) { w.create_body(def, shape); }, 240, recycling);
      const ShapeDef shapes[] = {part(shape, {0, 0})};
      const World compound = run_body([&](World& w) { w.create_body(def, shapes, 1); }, 240, recycling);
      EXPECT_EQ(plain.state_hash(), compound.state_hash())
          << "shape kind " << static_cast<int>(shape.type()) << ", recycling " << recycling;
    }
  }
}

TEST(Compound, ABoxSplitIntoTwoHalvesFollowsTheWholeBox) {
  // The halves stacked (top and bottom): only the bottom half touches, along the whole box's
  // bottom face. Dropped turned, it lands on a corner, rocks flat and slides to rest. The two
  // differ only by float rounding of the sums and of the halves' placement (a few ulps); a
  // landing amplifies that, so the bound is what the same box does with another recycling
  // setting (both are the method's error, not a difference of physics): a slide of about
  // 1.4 m ends within 1 mm.
  BodyDef def;
  def.position = {0.0f, 1.5f};
  def.angle = 0.2f;
  def.linear_velocity = {3.0f, 0.0f};
  def.material = rough();
  const int steps = 180;
  const World whole = run_body([&](World& w) { w.create_body(def, make_oriented_box({1.0f, 0.5f})); }, steps);
  const World whole_fresh =
      run_body([&](World& w) { w.create_body(def, make_oriented_box({1.0f, 0.5f})); }, steps, false);
  const Shape half = make_oriented_box({1.0f, 0.25f});
  const ShapeDef halves[] = {part(half, {0.0f, 0.25f}), part(half, {0.0f, -0.25f})};
  const World split = run_body([&](World& w) { w.create_body(def, halves, 2); }, steps);
  const BodyView a = whole.body(whole.body_ids()[1]);
  const BodyView fresh = whole_fresh.body(whole_fresh.body_ids()[1]);
  const BodyView b = split.body(split.body_ids()[1]);
  EXPECT_NEAR(b.mass, a.mass, a.mass * 4 * epsilon);
  EXPECT_NEAR(b.inertia, a.inertia, a.inertia * 1e-6f);
  const float recycling_spread = std::fabs(a.transform.position.x - fresh.transform.position.x);
  std::printf("[measured] whole box x %.6f (fresh manifolds %.6f), split %.6f; angles %.2e %.2e\n",
              a.transform.position.x, fresh.transform.position.x, b.transform.position.x, a.angle, b.angle);
  EXPECT_NEAR(b.transform.position.x, fresh.transform.position.x, 1e-3f);
  EXPECT_NEAR(b.transform.position.x, a.transform.position.x, std::max(1e-3f, 2 * recycling_spread));
  EXPECT_NEAR(b.transform.position.y, 0.5f, 5e-3f);  // resting on its face, within the slop
  EXPECT_NEAR(b.angle, a.angle, 1e-3f);
  EXPECT_FALSE(b.awake && std::fabs(b.linear_velocity.x) > 1e-2f);
}

TEST(Compound, ATStandsOnItsStemForTenSeconds) {
  // A 2 m bar on a 0.2 m wide, 1 m tall stem: its centre of mass high above a narrow foot.
  const ShapeDef shapes[] = {part(make_oriented_box({1.0f, 0.1f}), {0.0f, 1.1f}),
                             part(make_oriented_box({0.1f, 0.5f}), {0.0f, 0.5f})};
  World world;
  add_ground(world);
  BodyDef def;  // the stem's foot on the ground (y = 0)
  const BodyId t = world.create_body(def, shapes, 2);
  float lowest_foot = 0.0f;
  for (int i = 0; i < 600; ++i) {
    world.step();
    lowest_foot = std::min(lowest_foot, world.body(t).aabb.lower.y);
  }
  const BodyView view = world.body(t);
  EXPECT_LT(std::fabs(view.angle), 1e-4f);
  EXPECT_LT(std::fabs(view.transform.position.x), 1e-4f);
  EXPECT_GT(lowest_foot, -world.settings().slop - 1e-3f);
}

TEST(Compound, MirroredDropsStayMirrored) {
  // An L crate and its mirror image, dropped turned by opposite angles at x = -3 and x = +3:
  // each pose stays the other's mirror image through the landing, tumbling and rest.
  const Shape square = make_oriented_box({0.5f, 0.5f});
  World world;
  add_ground(world);
  BodyDef left;
  left.position = {-3.0f, 2.0f};
  left.angle = 0.3f;
  left.angular_velocity = 1.0f;
  BodyDef right = left;
  right.position.x = 3.0f;
  right.angle = -0.3f;
  right.angular_velocity = -1.0f;
  const ShapeDef shapes_left[] = {part(square, {0, 0}), part(square, {1, 0}), part(square, {0, 1})};
  const ShapeDef shapes_right[] = {part(square, {0, 0}), part(square, {-1, 0}), part(square, {0, 1})};
  const BodyId a = world.create_body(left, shapes_left, 3);
  const BodyId b = world.create_body(right, shapes_right, 3);
  float worst = 0.0f;
  for (int i = 0; i < 240; ++i) {
    world.step();
    const BodyView va = world.body(a);
    const BodyView vb = world.body(b);
    worst = std::max({worst, std::fabs(va.transform.position.x + vb.transform.position.x),
                      std::fabs(va.transform.position.y - vb.transform.position.y), std::fabs(va.angle + vb.angle)});
  }
  std::printf("[measured] mirrored L crates: largest asymmetry %.3g (m or rad)\n", worst);
  // Measured 0 with GCC 12 (the narrow phase and the solver are mirror-exact). The bound allows
  // rounding of a few ulps of 3 m, should a compiler order the mirrored sums differently; an
  // asymmetry of the method (a corner picked by index, a shape order that matters) shows
  // millimetres within the first bounce.
  EXPECT_LT(worst, 1e-5f);
}

TEST(Compound, EachShapeSlidesOnItsOwnMaterial) {
  // A slope of 20 degrees (tan = 0.36): a body whose lower shape is rough (mu_s 0.8) holds; the
  // same body with an icy lower shape slides, though its upper shape is rough.
  const float pi = 3.14159265f;
  const float slope = 20.0f * pi / 180.0f;
  auto run = [&](const Material& bottom) {
    World world;
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.angle = slope;
    ground.material = rough();
    world.create_body(ground, make_oriented_box({20.0f, 0.5f}));
    const Shape half = make_oriented_box({0.5f, 0.25f});
    const ShapeDef shapes[] = {part(half, {0.0f, 0.25f}, 0.0f, rough()), part(half, {0.0f, -0.25f}, 0.0f, bottom)};
    BodyDef def;
    def.angle = slope;
    def.position = vec2(-std::sin(slope), std::cos(slope)) * 1.0f;  // bottom face on the slope
    const BodyId body = world.create_body(def, shapes, 2);
    for (int i = 0; i < 120; ++i) world.step();
    return world.body(body).linear_velocity;
  };
  EXPECT_LT(std::sqrt(length_squared(run(rough()))), 1e-3f);
  // Frictionless: it slides at g sin(theta) after 2 s (minus the landing's first step).
  const vec2 sliding = run(ice());
  EXPECT_GT(std::sqrt(length_squared(sliding)), 0.9f * 10.0f * std::sin(slope) * 2.0f);
}

TEST(Compound, EachShapeCollidesByItsOwnLayers) {
  // The lower shape is on layer 2 only: it passes through the ground (layer 1), and the body
  // comes to rest on its upper shape.
  ShapeDef upper = part(make_oriented_box({0.5f, 0.25f}), {0.0f, 0.25f});
  ShapeDef lower = part(make_oriented_box({0.5f, 0.25f}), {0.0f, -0.25f});
  lower.collision_layers = 2;
  const ShapeDef shapes[] = {upper, lower};
  World world;
  add_ground(world);
  BodyDef def;
  def.position = {0.0f, 1.0f};
  const BodyId body = world.create_body(def, shapes, 2);
  for (int i = 0; i < 180; ++i) world.step();
  const BodyView view = world.body(body);
  // The upper shape's bottom face (0.25 above the body's centre at 1.0 - 0.0) rests on y = 0.
  EXPECT_NEAR(view.transform.position.y, 0.0f, 5e-3f);
  for (const Contact& contact : world.contacts()) EXPECT_EQ(contact.child_b, 0);
}

TEST(Compound, ContactEventsNameTheShapeThatTouches) {
  // A dumbbell of two discs lands on both; each disc's touch begins as its own event.
  const ShapeDef shapes[] = {part(make_circle(0.25f), {-1.0f, 0.0f}), part(make_circle(0.25f), {1.0f, 0.0f})};
  World world;
  const BodyId ground = add_ground(world);
  BodyDef def;
  def.position = {0.0f, 0.3f};
  const BodyId bell = world.create_body(def, shapes, 2);
  std::vector<int> began;
  for (int i = 0; i < 60; ++i) {
    world.step();
    for (const ContactBeginTouchEvent& event : world.contact_events().begin) {
      EXPECT_EQ(event.body_a, ground);
      EXPECT_EQ(event.body_b, bell);
      EXPECT_EQ(event.shape_b.body, bell);
      began.push_back(static_cast<int>(event.shape_b.index));
    }
  }
  ASSERT_EQ(began.size(), 2u);
  EXPECT_EQ(began[0], 0);
  EXPECT_EQ(began[1], 1);
  EXPECT_EQ(world.contacts().size(), 2u);
  // Level: both discs rest at their radius.
  EXPECT_NEAR(world.body(bell).transform.position.y, 0.25f, 1e-3f);
  EXPECT_LT(std::fabs(world.body(bell).angle), 1e-4f);
}

TEST(Compound, ASensorShapeSensesAndNeverTouches) {
  // A box with a foot sensor below it (as a character's ground sensor): the body lands on its
  // box; the foot overlaps the ground, which it reports (shape 1) and never pushes.
  ShapeDef foot = part(make_circle(0.2f), {0.0f, -0.4f});
  foot.is_sensor = true;
  const ShapeDef shapes[] = {part(make_oriented_box({0.5f, 0.25f}), {0.0f, 0.0f}), foot};
  World world;
  const BodyId ground = add_ground(world);
  BodyDef def;
  def.position = {0.0f, 1.0f};
  def.sensor_detects_static = true;
  const BodyId body = world.create_body(def, shapes, 2);
  int began = 0;
  for (int i = 0; i < 120; ++i) {
    world.step();
    for (const SensorBeginTouchEvent& event : world.sensor_events().begin) {
      EXPECT_EQ(event.sensor_shape.body, body);
      EXPECT_EQ(event.sensor_shape.index, 1u);
      EXPECT_EQ(event.visitor_shape.body, ground);
      ++began;
    }
    for (const Contact& contact : world.contacts()) EXPECT_EQ(contact.child_b, 0);
  }
  EXPECT_EQ(began, 1);
  // Resting on the box's bottom face (at y = 0, within the 5 mm slop), so the foot's lowest
  // point is 0.6 below the box's centre: 0.35 deep in the ground.
  EXPECT_NEAR(world.body(body).aabb.lower.y, -0.35f, world.settings().slop);
  EXPECT_LT(std::fabs(world.body(body).angle), 1e-4f);
  // Queries skip a sensor shape unless asked.
  QueryFilter solid;
  EXPECT_EQ(world.overlap_shape(make_circle(0.05f), Transform{world.body(body).transform.apply({0.0f, -0.4f}), Rotation{}},
                                nullptr, 0, solid),
            1);  // the ground only
  QueryFilter with_sensors;
  with_sensors.include_sensors = true;
  EXPECT_EQ(world.overlap_shape(make_circle(0.05f), Transform{world.body(body).transform.apply({0.0f, -0.4f}), Rotation{}},
                                nullptr, 0, with_sensors),
            2);
}

TEST(Compound, QueriesSeeEveryShape) {
  const ShapeDef shapes[] = {part(make_oriented_box({0.5f, 0.5f}), {0.0f, 0.0f}),
                             part(make_circle(0.5f), {3.0f, 0.0f})};
  World world;
  BodyDef def;
  def.type = BodyType::Static;
  const BodyId body = world.create_body(def, shapes, 2);
  int found = 0;
  world.query_point({3.2f, 0.1f}, [&](BodyId id) { found += id == body; return true; });
  EXPECT_EQ(found, 1);
  found = 0;
  world.query_point({1.5f, 0.0f}, [&](BodyId) { ++found; return true; });  // between the shapes
  EXPECT_EQ(found, 0);
  const auto hit = world.raycast_closest({3.0f, 5.0f}, {0.0f, -10.0f});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->point.y, 0.5f, 1e-5f);
  EXPECT_FALSE(world.raycast_closest({1.5f, 5.0f}, {0.0f, -10.0f}).has_value());
  BodyId out[2];
  EXPECT_EQ(world.overlap_shape(make_circle(0.2f), Transform{{3.6f, 0.0f}, Rotation{}}, out, 2), 1);
  EXPECT_EQ(world.overlap_shape(make_circle(0.2f), Transform{{1.5f, 0.0f}, Rotation{}}, out, 2), 0);
  const auto cast = world.cast_shape(make_circle(0.25f), Transform{{6.0f, 0.0f}, Rotation{}}, {-6.0f, 0.0f});
  ASSERT_TRUE(cast.has_value());
  EXPECT_NEAR(cast->fraction, (6.0f - 3.5f - 0.25f) / 6.0f, 1e-5f);
}

TEST(Compound, SnapshotRestoresAndContinuesBitForBit) {
  const ShapeDef shapes[] = {part(make_oriented_box({0.5f, 0.1f}), {0.0f, 0.0f}),
                             part(make_capsule({0.0f, 0.0f}, {0.0f, 0.6f}, 0.1f), {0.4f, 0.3f}, 0.0f, ice())};
  World world;
  add_ground(world);
  BodyDef def;
  def.position = {0.0f, 1.0f};
  def.angular_velocity = 2.0f;
  world.create_body(def, shapes, 2);
  for (int i = 0; i < 40; ++i) world.step();
  const std::vector<std::uint8_t> bytes = world.save_snapshot();
  World restored;
  restored.restore_snapshot(bytes);
  EXPECT_EQ(restored.save_snapshot(), bytes);
  for (int i = 0; i < 60; ++i) {
    world.step();
    restored.step();
  }
  EXPECT_EQ(restored.state_hash(), world.state_hash());
}

TEST(Compound, BadShapesAreRefusedNamingTheShape) {
  World world;
  auto message = [&](const BodyDef& def, const std::vector<ShapeDef>& shapes) -> std::string {
    try {
      world.create_body(def, shapes.data(), static_cast<int>(shapes.size()));
    } catch (const Error& error) {
      return error.what();
    }
    return "";
  };
  const ShapeDef good = part(make_circle(0.5f), {0, 0});
  ShapeDef bad_radius = good;
  bad_radius.shape = Circle{-1.0f};
  EXPECT_NE(message(BodyDef{}, {good, bad_radius}).find("shapes[1]: circle radius"), std::string::npos);
  ShapeDef not_finite = good;
  not_finite.position.x = NAN;
  EXPECT_NE(message(BodyDef{}, {not_finite}).find("shapes[0]: position"), std::string::npos);
  EXPECT_NE(message(BodyDef{}, {}).find("1..256 shapes"), std::string::npos);
  const ShapeDef segment = part(make_segment({-1, 0}, {1, 0}), {0, 0});
  EXPECT_NE(message(BodyDef{}, {segment, segment}).find("needs a shape with area"), std::string::npos);
  const vec2 points[] = {{0, 0}, {1, 0}, {2, 0}};
  ShapeDef link = good;
  link.shape = make_chain(points, 3, false)[0].shape;
  EXPECT_NE(message(BodyDef{}, {good, link}).find("shapes[1]: a chain link"), std::string::npos);
  ShapeDef weightless = good;
  weightless.material.density = 0.0f;
  EXPECT_NE(message(BodyDef{}, {good, weightless}).find("shapes[1]: a dynamic body's shapes need"),
            std::string::npos);
  EXPECT_EQ(world.body_count(), 0);
  // A segment beside a shape with area is fine on a dynamic body (it adds no mass).
  const ShapeDef with_blade[] = {good, segment};
  const BodyView view = world.body(world.create_body(BodyDef{}, with_blade, 2));
  EXPECT_NEAR(view.mass, 0.25f * 3.14159265f, 1e-6f);
}

}  // namespace
}  // namespace impulse2d
