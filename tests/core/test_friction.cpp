// Coulomb friction with static and dynamic coefficients against exact answers:
//  - a block on an incline holds iff tan(theta) <= mu_s, else accelerates at g (sin - mu_d cos);
//  - a block sliding on flat ground stops after v0^2 / (2 mu_d g);
//  - a disc rolls down a slope at 2/3 g sin(theta) when mu_s >= tan(theta) / 3.
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace impulse2d;

namespace {

constexpr float g = 9.81f;
constexpr float pi = 3.14159265358979f;

Material surface(float static_friction, float dynamic_friction) {
  return Material{"Surface", 1.0f, 0.0f, static_friction, dynamic_friction};
}

WorldSettings friction_settings(SolverMethod solver = SolverMethod::Accumulated) {
  WorldSettings settings;
  settings.friction_mixing = FrictionMixing::Minimum;  // both bodies carry the same coefficients
  settings.solver = solver;
  return settings;
}

// A static slab tilted by theta whose top face passes through the origin, and a body resting
// on it at distance 0 along the slope. Returns the body's handle.
BodyId place_on_incline(World& world, float theta, const Material& material, const Shape& shape,
                        float height_above_face) {
  const vec2 down_slope{-std::cos(theta), -std::sin(theta)};  // slope rises to the right
  const vec2 up_normal{-std::sin(theta), std::cos(theta)};
  BodyDef slab;
  slab.type = BodyType::Static;
  slab.material = material;
  slab.material.density = 0.0f;
  slab.angle = theta;
  slab.position = up_normal * -0.5f;  // half thickness below the face
  world.create_body(slab, make_oriented_box({20.0f, 0.5f}));
  (void)down_slope;
  BodyDef body;
  body.material = material;
  body.angle = theta;
  body.position = up_normal * height_above_face;
  return world.create_body(body, shape);
}

// Distance travelled down the slope since the start.
float down_slope_distance(const World& world, BodyId id, float theta, vec2 start) {
  const vec2 down_slope{-std::cos(theta), -std::sin(theta)};
  return glm::dot(world.body(id).transform.position - start, down_slope);
}

float down_slope_speed(const World& world, BodyId id, float theta) {
  return glm::dot(world.body(id).linear_velocity, vec2(-std::cos(theta), -std::sin(theta)));
}

}  // namespace

TEST(Incline, BlockHoldsWhenTanThetaIsBelowStaticFriction) {
  const float theta = 30.0f * pi / 180.0f;  // tan = 0.577
  World world(friction_settings());
  const BodyId block = place_on_incline(world, theta, surface(0.60f, 0.30f),
                                        make_oriented_box({0.5f, 0.25f}), 0.25f);
  const vec2 start = world.body(block).transform.position;
  for (int i = 0; i < 120; ++i) world.step();  // 2 s
  // Holding means no sliding at all; only the settling into the slop may move it.
  EXPECT_LT(std::fabs(down_slope_distance(world, block, theta, start)), world.settings().slop);
  EXPECT_LT(std::fabs(down_slope_speed(world, block, theta)), 1e-3f);
}

TEST(Incline, BlockSlidesAtTheDynamicFrictionAccelerationWhenStaticFrictionIsExceeded) {
  const float theta = 30.0f * pi / 180.0f;
  const float mu_d = 0.30f;
  World world(friction_settings());
  const BodyId block = place_on_incline(world, theta, surface(0.55f, mu_d),
                                        make_oriented_box({0.5f, 0.25f}), 0.25f);
  for (int i = 0; i < 30; ++i) world.step();
  const float v1 = down_slope_speed(world, block, theta);
  for (int i = 0; i < 60; ++i) world.step();
  const float v2 = down_slope_speed(world, block, theta);
  const float measured = (v2 - v1) / (60 * world.settings().time_step);
  const float expected = g * (std::sin(theta) - mu_d * std::cos(theta));
  // Steady sliding is a fixed point of the iteration: the total normal impulse cancels gravity's
  // normal part and friction is exactly mu_d times it, so only float rounding of the summed
  // velocities is left (60 steps of ~1e-7 relative).
  EXPECT_NEAR(measured, expected, 1e-3f * expected);
}

TEST(Incline, HoldsJustBelowAndSlidesJustAboveTheCriticalAngle) {
  const float mu_s = 0.5f;
  const float critical = std::atan(mu_s);
  for (float offset : {-0.02f, +0.02f}) {
    World world(friction_settings());
    const float theta = critical + offset;
    const BodyId block = place_on_incline(world, theta, surface(mu_s, 0.4f),
                                          make_oriented_box({0.5f, 0.25f}), 0.25f);
    const vec2 start = world.body(block).transform.position;
    for (int i = 0; i < 120; ++i) world.step();
    const float travelled = down_slope_distance(world, block, theta, start);
    if (offset < 0) {
      EXPECT_LT(std::fabs(travelled), world.settings().slop) << "should hold at theta " << theta;
    } else {
      // Above critical it slides with a = g (sin - 0.4 cos) > 0 for 2 s.
      const float a = g * (std::sin(theta) - 0.4f * std::cos(theta));
      EXPECT_GT(travelled, 0.5f * a * 4.0f * 0.9f) << "should slide at theta " << theta;
    }
  }
}

TEST(Slide, StoppingDistanceIsV0SquaredOverTwoMuG) {
  // Axis-aligned boxes: no rotation, two contact points, the model a platformer uses.
  for (SolverMethod solver : {SolverMethod::Accumulated, SolverMethod::PerIteration}) {
    World world(friction_settings(solver));
    const float mu_d = 0.4f, v0 = 5.0f;
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.material = surface(0.6f, mu_d);
    ground.material.density = 0.0f;
    ground.position = {0, -0.5f};
    world.create_body(ground, make_box({50, 0.5f}));
    BodyDef block;
    block.material = surface(0.6f, mu_d);
    block.position = {0, 0.25f};
    block.linear_velocity = {v0, 0};
    const BodyId id = world.create_body(block, make_box({0.5f, 0.25f}));
    for (int i = 0; i < 240; ++i) world.step();
    const float dt = world.settings().time_step;
    EXPECT_NEAR(world.body(id).linear_velocity.x, 0.0f, 1e-4f);
    // Semi-implicit Euler moves v0 dt / 2 less than the continuous answer, and stops within a
    // step: tolerance one step of travel.
    EXPECT_NEAR(world.body(id).transform.position.x, v0 * v0 / (2 * mu_d * g), v0 * dt)
        << "solver " << static_cast<int>(solver);
  }
}

TEST(Rolling, DiscRollsAtTwoThirdsGSinTheta) {
  const float theta = 20.0f * pi / 180.0f;  // needs mu_s >= tan/3 = 0.121
  World world(friction_settings());
  const float radius = 0.5f;
  const BodyId disc = place_on_incline(world, theta, surface(0.3f, 0.2f), make_circle(radius), radius);
  for (int i = 0; i < 30; ++i) world.step();
  const float v1 = down_slope_speed(world, disc, theta);
  for (int i = 0; i < 60; ++i) world.step();
  const float v2 = down_slope_speed(world, disc, theta);
  const float measured = (v2 - v1) / (60 * world.settings().time_step);
  const float expected = 2.0f / 3.0f * g * std::sin(theta);
  // One contact point through the centre: the normal and friction rows are decoupled, so the
  // iteration solves them exactly. What remains is geometry: the contact point is the middle
  // of the overlap, which the solver allows up to `slop` deep, so the lever arm is
  // rho = r - d/2 with d <= slop. Then a = g sin / (1 + (r / rho)^2 / 2) errs by at most
  // slop / (3 r) relative, and v = w rho differs from w r by at most slop / (2 r).
  const float slop = world.settings().slop;
  EXPECT_NEAR(measured, expected, expected * slop / (3 * radius));
  // Rolling without slipping: rolling down to the left spins counter-clockwise, v = w r.
  EXPECT_NEAR(v2, world.body(disc).angular_velocity * radius, v2 * slop / (2 * radius));
}

TEST(Rolling, DiscSlipsWhenStaticFrictionIsBelowTanThetaOverThree) {
  const float theta = 30.0f * pi / 180.0f;  // tan/3 = 0.192
  const float mu_d = 0.10f;
  World world(friction_settings());
  const BodyId disc = place_on_incline(world, theta, surface(0.15f, mu_d), make_circle(0.5f), 0.5f);
  for (int i = 0; i < 30; ++i) world.step();
  const float v1 = down_slope_speed(world, disc, theta);
  for (int i = 0; i < 60; ++i) world.step();
  const float v2 = down_slope_speed(world, disc, theta);
  const float measured = (v2 - v1) / (60 * world.settings().time_step);
  const float expected = g * (std::sin(theta) - mu_d * std::cos(theta));
  EXPECT_NEAR(measured, expected, 1e-3f * expected);
}

TEST(FrictionMixing, RulesCombineAsDocumented) {
  EXPECT_FLOAT_EQ(mix_friction(0.3f, 0.4f, FrictionMixing::RootSumSquares), 0.5f);
  EXPECT_FLOAT_EQ(mix_friction(0.25f, 1.0f, FrictionMixing::GeometricMean), 0.5f);
  EXPECT_FLOAT_EQ(mix_friction(0.5f, 0.4f, FrictionMixing::Product), 0.2f);
  EXPECT_FLOAT_EQ(mix_friction(0.2f, 0.4f, FrictionMixing::Average), 0.3f);
  EXPECT_FLOAT_EQ(mix_friction(0.2f, 0.4f, FrictionMixing::Minimum), 0.2f);
  EXPECT_FLOAT_EQ(mix_friction(0.2f, 0.4f, FrictionMixing::Maximum), 0.4f);
  EXPECT_FLOAT_EQ(mix_restitution(0.2f, 0.4f, RestitutionMixing::Minimum), 0.2f);
  EXPECT_FLOAT_EQ(mix_restitution(0.2f, 0.4f, RestitutionMixing::Maximum), 0.4f);
  EXPECT_FLOAT_EQ(mix_restitution(0.2f, 0.4f, RestitutionMixing::Average), 0.3f);
}

TEST(Materials, TutorialTableIsComplete) {
  const std::vector<Material> all = materials::all();
  ASSERT_EQ(all.size(), 7u);
  EXPECT_FLOAT_EQ(materials::by_name("Rock").density, 0.6f);
  EXPECT_FLOAT_EQ(materials::by_name("SuperBall").restitution, 0.95f);
  EXPECT_FLOAT_EQ(materials::by_name("Static").density, 0.0f);
  for (const Material& m : all) EXPECT_GE(m.static_friction, m.dynamic_friction) << m.name;
  EXPECT_THROW(materials::by_name("Jelly"), std::exception);
}
