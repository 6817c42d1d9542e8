// SolverMethod::SoftStep (Box2D v3's soft step) against the same exact answers as the other
// solvers. Settings are Box2D v3's: 4 sub-steps of one soft pass and one relax pass each,
// contact hertz 30, damping ratio 10, push-out at most 3 m/s.
#include "bounce_apexes.h"
#include "core/error.h"
#include "core/solver/softness.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace impulse2d;

namespace {

constexpr float g = 9.81f;
constexpr float pi = 3.14159265358979f;

WorldSettings soft_settings() {
  WorldSettings settings;
  settings.solver = SolverMethod::SoftStep;
  settings.substeps = 4;
  settings.velocity_iterations = 1;
  return settings;
}

// Accumulated rounding: one half-ulp-scale error per (sub)step on values of size `scale`.
double rounding_bound(int steps, double scale) { return steps * scale * std::ldexp(1.0, -23); }

void add_ground(World& world, float half_width) {
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0, -0.5f};
  world.create_body(ground, make_box({half_width, 0.5f}));
}

BodyId build_stack(World& world, int boxes) {
  add_ground(world, 20.0f);
  BodyId top;
  for (int i = 0; i < boxes; ++i) {
    BodyDef def;
    def.material = materials::wood();
    def.position = {0, 0.5f + static_cast<float>(i)};
    top = world.create_body(def, make_oriented_box({0.5f, 0.5f}));
  }
  return top;
}

Material surface(float static_friction, float dynamic_friction) {
  return Material{"Surface", 1.0f, 0.0f, static_friction, dynamic_friction};
}

// A static slab tilted by theta whose top face passes through the origin, and a block resting
// on it, `overlap` metres into the slab. Returns the block's handle.
BodyId place_on_incline(World& world, float theta, const Material& material, float overlap) {
  const vec2 up_normal{-std::sin(theta), std::cos(theta)};
  BodyDef slab;
  slab.type = BodyType::Static;
  slab.material = material;
  slab.material.density = 0.0f;
  slab.angle = theta;
  slab.position = up_normal * -0.5f;
  world.create_body(slab, make_oriented_box({20.0f, 0.5f}));
  BodyDef block;
  block.material = material;
  block.angle = theta;
  block.position = up_normal * (0.25f - overlap);
  return world.create_body(block, make_oriented_box({0.5f, 0.25f}));
}

vec2 down_slope(float theta) { return {-std::cos(theta), -std::sin(theta)}; }

}  // namespace

TEST(SoftStep, MakeSoftMatchesTheImplicitSpringDamperFormulas) {
  const double hertz = 30, zeta = 10, h = 1.0 / 240;
  const double omega = 2 * 3.14159265358979 * hertz;
  const double a = 2 * zeta + h * omega;
  const Softness softness = make_soft(30.0f, 10.0f, 1.0f / 240.0f);
  EXPECT_NEAR(softness.bias_rate, omega / a, 1e-5 * omega / a);
  EXPECT_NEAR(softness.mass_scale, h * omega * a / (1 + h * omega * a), 1e-6);
  EXPECT_NEAR(softness.impulse_scale, 1 / (1 + h * omega * a), 1e-6);
  EXPECT_NEAR(softness.mass_scale + softness.impulse_scale, 1.0, 1e-6);
}

TEST(SoftStep, SettingsAreValidatedByName) {
  for (const char* field : {"contact_hertz", "contact_damping_ratio", "contact_push_max_speed"}) {
    WorldSettings settings = soft_settings();
    const std::string name = field;
    if (name == "contact_hertz") settings.contact_hertz = 0.0f;
    if (name == "contact_damping_ratio") settings.contact_damping_ratio = -1.0f;
    if (name == "contact_push_max_speed") settings.contact_push_max_speed = std::nanf("");
    try {
      World world(settings);
      ADD_FAILURE() << field << " was accepted";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(std::string("WorldSettings.") + field), std::string::npos)
          << error.what();
    }
  }
}

TEST(SoftStep, FreeFallMatchesSemiImplicitEulerPerSubStep) {
  // No contacts: each sub-step of h = dt / substeps is semi-implicit Euler at h, so after
  // t = n dt the height errs by exactly -g t h / 2, up to float rounding.
  for (int substeps : {1, 4, 8}) {
    WorldSettings settings = soft_settings();
    settings.substeps = substeps;
    World world(settings);
    BodyDef def;
    def.position = {0.0f, 100.0f};
    def.linear_velocity = {3.0f, 12.0f};
    const BodyId body = world.create_body(def, make_circle(0.25f));
    for (int i = 0; i < 120; ++i) world.step();
    const double t = 2.0, h = 1.0 / 60 / substeps, gd = 9.81;
    const double exact = 100.0 + 12.0 * t - gd * t * t / 2;
    const int substeps_taken = 120 * substeps;
    EXPECT_NEAR(world.body(body).transform.position.y - exact, -gd * t * h / 2,
                rounding_bound(substeps_taken, 130.0))
        << substeps << " sub-steps";
    EXPECT_NEAR(world.body(body).linear_velocity.y, 12.0 - gd * t, rounding_bound(substeps_taken, 20.0));
    EXPECT_NEAR(world.body(body).transform.position.x, 3.0 * t, rounding_bound(substeps_taken, 10.0));
  }
}

TEST(SoftStep, RestingBoxDoesNotDrift) {
  World world(soft_settings());
  const BodyId box = build_stack(world, 1);
  for (int i = 0; i < 60; ++i) world.step();
  const vec2 settled = world.body(box).transform.position;
  for (int i = 0; i < 600; ++i) world.step();
  const BodyView body = world.body(box);
  EXPECT_LT(glm::length(body.transform.position - settled), world.settings().slop);
  EXPECT_LT(std::fabs(body.angle), 1e-3f);
  EXPECT_GT(body.transform.position.y, 0.5f - world.settings().slop);
}

TEST(SoftStep, TenBoxStackDoesNotDrift) {
  World world(soft_settings());
  const BodyId top = build_stack(world, 10);
  for (int i = 0; i < 60; ++i) world.step();
  const vec2 settled = world.body(top).transform.position;
  // Each of the 10 contacts may keep up to `slop` of overlap.
  EXPECT_GT(settled.y, 9.5f - 10 * world.settings().slop);
  for (int i = 0; i < 600; ++i) world.step();
  EXPECT_LT(glm::length(world.body(top).transform.position - settled), world.settings().slop);
  EXPECT_LT(std::fabs(world.body(top).angle), 1e-2f);
}

TEST(SoftStep, TwentyRowPyramidBuiltInContactStaysStanding) {
  // The bench's pyramid, but built resting in contact (1 mm overlap per contact, below the
  // slop): collision runs once per step and the narrow phase reports no speculative contacts,
  // so the bench's pyramid, built exactly touching, first falls as a cascade of impacts (see
  // README). Standing means: after 2 s of settling nothing drifts more than the slop in 8 s,
  // no box moved sideways half the 5 cm gap between neighbours (so none touched another in its
  // row), and none sank more than the slop each contact below it may keep.
  World world(soft_settings());
  const int rows = 20;
  const float overlap = 0.001f, gap = 0.05f;
  add_ground(world, rows + 10.0f);
  std::vector<BodyId> boxes;
  std::vector<vec2> start;
  std::vector<int> row_of;
  for (int row = 0; row < rows; ++row) {
    for (int i = 0; i < rows - row; ++i) {
      BodyDef def;
      def.material = materials::wood();
      def.position = {(static_cast<float>(i) - 0.5f * static_cast<float>(rows - row - 1)) * (1.0f + gap),
                      0.5f + static_cast<float>(row) - static_cast<float>(row + 1) * overlap};
      boxes.push_back(world.create_body(def, make_oriented_box({0.5f, 0.5f})));
      start.push_back(def.position);
      row_of.push_back(row);
    }
  }
  for (int i = 0; i < 120; ++i) world.step();
  std::vector<vec2> settled;
  for (BodyId id : boxes) settled.push_back(world.body(id).transform.position);
  for (int i = 0; i < 480; ++i) world.step();
  const float slop = world.settings().slop;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const vec2 position = world.body(boxes[i]).transform.position;
    EXPECT_LT(glm::length(position - settled[i]), slop) << "box " << i << " drifted";
    EXPECT_LT(std::fabs(position.x - start[i].x), 0.5f * gap) << "box " << i;
    EXPECT_GT(position.y - start[i].y, -static_cast<float>(row_of[i] + 1) * slop) << "box " << i;
  }
}

TEST(SoftStep, InclineHoldsIffTanThetaIsBelowStaticFriction) {
  const float mu_s = 0.5f, mu_d = 0.4f;
  const float critical = std::atan(mu_s);
  for (float offset : {-0.02f, +0.02f}) {
    WorldSettings settings = soft_settings();
    settings.friction_mixing = FrictionMixing::Minimum;
    World world(settings);
    const float theta = critical + offset;
    // Starts resting in contact (1 mm overlap, below the slop): the static case, no impact.
    const BodyId block = place_on_incline(world, theta, surface(mu_s, mu_d), 0.001f);
    const vec2 start = world.body(block).transform.position;
    for (int i = 0; i < 120; ++i) world.step();
    const float travelled = glm::dot(world.body(block).transform.position - start, down_slope(theta));
    if (offset < 0) {
      EXPECT_LT(std::fabs(travelled), settings.slop) << "should hold at theta " << theta;
      EXPECT_LT(std::fabs(glm::dot(world.body(block).linear_velocity, down_slope(theta))), 1e-3f);
    } else {
      const float a = g * (std::sin(theta) - mu_d * std::cos(theta));
      EXPECT_GT(travelled, 0.5f * a * 4.0f * 0.9f) << "should slide at theta " << theta;
    }
  }
}

TEST(SoftStep, SlidesAtTheDynamicFrictionAcceleration) {
  const float theta = 30.0f * pi / 180.0f;
  const float mu_d = 0.30f;
  WorldSettings settings = soft_settings();
  settings.friction_mixing = FrictionMixing::Minimum;
  World world(settings);
  const BodyId block = place_on_incline(world, theta, surface(0.55f, mu_d), 0.0f);
  for (int i = 0; i < 30; ++i) world.step();
  const float v1 = glm::dot(world.body(block).linear_velocity, down_slope(theta));
  for (int i = 0; i < 60; ++i) world.step();
  const float v2 = glm::dot(world.body(block).linear_velocity, down_slope(theta));
  const float measured = (v2 - v1) / (60 * settings.time_step);
  const float expected = g * (std::sin(theta) - mu_d * std::cos(theta));
  // Steady sliding: the relax pass ends each sub-step with the normal impulse cancelling
  // gravity's normal part and friction at exactly mu_d times it; only rounding is left.
  EXPECT_NEAR(measured, expected, 1e-3f * expected);
}


class SoftBounce : public ::testing::TestWithParam<float> {};

TEST_P(SoftBounce, ApexHeightsFollowESquaredPowers) {
  // The error bound of bounce_apexes.h holds here too: restitution uses the speed at the
  // step's start (<= g dt off) and soft contacts push the ball back out of the floor.
  const float e = GetParam();
  const double h0 = 2.0, gd = 9.81;
  const float dt = 1.0f / 240.0f;
  const int bounces = 4;
  WorldSettings settings = soft_settings();
  settings.time_step = dt;
  const std::vector<double> apexes = bounce_test::bounce_apexes(settings, e, static_cast<float>(h0), bounces);
  ASSERT_EQ(apexes.size(), static_cast<std::size_t>(bounces));
  for (int k = 1; k <= bounces; ++k) {
    EXPECT_NEAR(apexes[static_cast<std::size_t>(k - 1)], std::pow(e, 2 * k) * h0,
                bounce_test::bounce_apex_tolerance(e, h0, gd, dt, k))
        << "bounce " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Restitution, SoftBounce, ::testing::Values(0.5f, 0.8f, 0.95f));

TEST(SoftStep, PositionCorrectionSettingsAreIgnored) {
  // Soft contacts replace position correction: changing it changes nothing, bit for bit.
  WorldSettings with_ngs = soft_settings();
  WorldSettings with_none = soft_settings();
  with_none.position_correction = PositionCorrection::None;
  with_none.correction_percent = 0.9f;
  World first(with_ngs);
  World second(with_none);
  build_stack(first, 5);
  build_stack(second, 5);
  for (int i = 0; i < 120; ++i) {
    first.step();
    second.step();
  }
  EXPECT_EQ(first.state_hash(), second.state_hash());
}

TEST(SoftStep, TwoWorldsBuiltAlikeHaveIdenticalHashes) {
  World first(soft_settings());
  World second(soft_settings());
  for (World* world : {&first, &second}) {
    build_stack(*world, 6);
    BodyDef ball;
    ball.material = materials::bouncy_ball();
    ball.position = {0.3f, 9.0f};
    ball.linear_velocity = {-1.0f, -4.0f};
    world->create_body(ball, make_circle(0.3f));
  }
  for (int i = 0; i < 600; ++i) {
    first.step();
    second.step();
    ASSERT_EQ(first.state_hash(), second.state_hash()) << "diverged at step " << i;
  }
}
