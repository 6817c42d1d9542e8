// The soft step's compact body states (core/solver_bodies.h) integrate bit for bit as
// integrate.h does on the world's bodies: every kind of body, every switch, the speed clamp.
#include "core/solver/integrate.h"
#include "core/solver/solver_bodies.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using namespace impulse2d;

namespace {

Body make_body(BodyType type, ShapeType shape, vec2 velocity, float angular_velocity) {
  Body body;
  body.type = type;
  body.shape = shape == ShapeType::Circle ? make_circle(0.5f)
               : shape == ShapeType::Box  ? make_box({0.5f, 0.25f})
                                          : make_oriented_box({0.5f, 0.25f});
  body.transform.position = {1.25f, -3.5f};
  body.angle = 0.3f;
  body.transform.rotation = Rotation::from_angle(body.angle);
  body.linear_velocity = velocity;
  body.angular_velocity = angular_velocity;
  if (type == BodyType::Dynamic) {
    body.mass = 2.0f;
    body.inverse_mass = 0.5f;
    body.inertia = 0.4f;
    body.inverse_inertia = 2.5f;
  }
  return body;
}

// One of each case integrate.h distinguishes.
std::vector<Body> every_kind_of_body() {
  std::vector<Body> bodies;
  bodies.push_back(make_body(BodyType::Dynamic, ShapeType::Polygon, {1.0f, 2.0f}, 3.0f));
  bodies.back().force = {4.0f, -1.5f};
  bodies.back().torque = 0.75f;
  bodies.back().linear_damping = 0.3f;
  bodies.back().angular_damping = 1.7f;
  bodies.back().gravity_scale = 0.5f;
  bodies.push_back(make_body(BodyType::Dynamic, ShapeType::Circle, {-2.0f, 0.5f}, -1.0f));
  bodies.back().fixed_rotation = true;  // its angular velocity is zeroed, its angle kept
  bodies.push_back(make_body(BodyType::Dynamic, ShapeType::Box, {0.5f, 0.5f}, 2.0f));  // no spin
  bodies.push_back(make_body(BodyType::Dynamic, ShapeType::Polygon, {300.0f, 300.0f}, 0.0f));
  bodies.push_back(make_body(BodyType::Kinematic, ShapeType::Polygon, {0.5f, -0.25f}, 1.5f));
  bodies.push_back(make_body(BodyType::Static, ShapeType::Polygon, {0.0f, 0.0f}, 0.0f));
  bodies.push_back(make_body(BodyType::Dynamic, ShapeType::Polygon, {1.0f, 0.0f}, 1.0f));
  bodies.back().awake = false;  // asleep: left alone
  bodies.push_back(make_body(BodyType::Dynamic, ShapeType::Polygon, {7.0f, 7.0f}, 7.0f));
  return bodies;  // the last one's slot is dead (see `alive` below)
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_motion(const Body& expected, const Body& actual, int slot) {
  SCOPED_TRACE(slot);
  EXPECT_TRUE(same_bits(expected.linear_velocity.x, actual.linear_velocity.x));
  EXPECT_TRUE(same_bits(expected.linear_velocity.y, actual.linear_velocity.y));
  EXPECT_TRUE(same_bits(expected.angular_velocity, actual.angular_velocity));
  EXPECT_TRUE(same_bits(expected.transform.position.x, actual.transform.position.x));
  EXPECT_TRUE(same_bits(expected.transform.position.y, actual.transform.position.y));
  EXPECT_TRUE(same_bits(expected.transform.rotation.cosine, actual.transform.rotation.cosine));
  EXPECT_TRUE(same_bits(expected.transform.rotation.sine, actual.transform.rotation.sine));
  EXPECT_TRUE(same_bits(expected.angle, actual.angle));
}

}  // namespace

TEST(SolverBodies, IntegrateBitForBitAsTheBodiesDo) {
  for (const bool rotation : {true, false}) {
    WorldSettings settings;
    settings.enable_rotation = rotation;
    settings.max_linear_speed = 100.0f;  // the fourth body starts above it
    const std::vector<std::uint8_t> alive = {1, 1, 1, 1, 1, 1, 1, 0};
    std::vector<Body> expected = every_kind_of_body();
    std::vector<Body> actual = expected;
    SolverBodies states;
    states.begin_step(actual, alive, settings);
    const float h = 1.0f / 240.0f;
    for (int substep = 0; substep < 4; ++substep) {
      integrate_velocities(expected, alive, settings, h);
      integrate_positions(expected, alive, settings, h);
      states.integrate_velocities(h);
      states.integrate_positions(h);
    }
    states.store(actual);
    for (std::size_t i = 0; i < expected.size(); ++i) {
      expect_same_motion(expected[i], actual[i], static_cast<int>(i));
    }
    // The dead slot is never written, even though its velocity would move it.
    EXPECT_EQ(actual.back().transform.position, every_kind_of_body().back().transform.position);
    // The clamp acted, and rotation followed the switch.
    EXPECT_LE(glm::length(actual[3].linear_velocity), 100.0f * (1.0f + 1e-6f));
    EXPECT_EQ(actual[0].angle != 0.3f, rotation);
  }
}

TEST(SolverBodies, LoadReadsBackWhatAnOutsideStageChanged) {
  WorldSettings settings;
  const std::vector<std::uint8_t> alive(8, 1);
  std::vector<Body> bodies = every_kind_of_body();
  SolverBodies states;
  states.begin_step(bodies, alive, settings);
  bodies[0].linear_velocity = {-5.0f, 0.25f};  // e.g. a bounce or a bullet moved back
  bodies[0].transform.position = {9.0f, 9.0f};
  bodies[6].linear_velocity = {0.5f, 0.5f};  // asleep: a contact may still change its velocity
  states.load(bodies);
  std::vector<Body> stored = every_kind_of_body();
  states.store(stored);
  EXPECT_EQ(stored[0].linear_velocity, vec2(-5.0f, 0.25f));
  EXPECT_EQ(stored[0].transform.position, vec2(9.0f, 9.0f));
  EXPECT_EQ(stored[6].linear_velocity, vec2(0.5f, 0.5f));
  EXPECT_EQ(stored[6].transform.position, every_kind_of_body()[6].transform.position);
  EXPECT_FALSE(states.has_bullets());
  bodies[0].is_bullet = true;
  states.begin_step(bodies, alive, settings);
  EXPECT_TRUE(states.has_bullets());
}
